// RecoveryWriter: the autosave thread's file work (private to the model; see autosaver.h).
#pragma once

#include "../finbook_file_tr.h"

#include <finbook/model/io/atomic_file.h>
#include <finbook/model/recovery/recovery_store.h>

#include <QFile>
#include <QFileInfo>
#include <QObject>

#include <new>

namespace finbook::model {

// Lives on the autosave thread and does its file work there, one job at a time, in order.
class RecoveryWriter : public QObject {
    Q_OBJECT
public:
    struct Snapshot {
        std::vector<Layer> layers;
        DocumentSettings settings;
        RecoveryInfo info;
        QString path;
        Reference reference; // the reference layer (its media bytes shared)
        std::vector<SoundClip> sound;
        CameraTrack camera;
        Palette palette;
        std::vector<SwapSet> swapSets;
    };

    void write(const Snapshot &snapshot)
    {
        QString error;
        try {
            const QByteArray bytes = recoveryCopyBytes(
                snapshot.layers, snapshot.settings, snapshot.info, snapshot.reference,
                snapshot.sound, snapshot.camera, snapshot.palette, snapshot.swapSets);
            if (const auto failure = writeFileAtomically(snapshot.path, bytes))
                error = describeWriteFailure(*failure, QFileInfo(snapshot.path).absolutePath());
        } catch (const std::bad_alloc &) {
            error = file_format::FinbookFile::tr("there is not enough memory");
        }
        emit finished(snapshot.path, error);
    }
    void remove(const QString &path) { QFile::remove(path); }
    void rename(const QString &from, const QString &to)
    {
        QFile::remove(to);
        QFile::rename(from, to);
    }

signals:
    void finished(const QString &path, const QString &error);
};

} // namespace finbook::model
