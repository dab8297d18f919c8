#include <finbook/model/document.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/sound/sound_controller.h>
#include <finbook/ui/sound/sound_player.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/window/editor_state.h>

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QPointer>
#include <QThreadPool>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <memory>

namespace finbook::ui {

qint64 startTickOfFrame(const model::Document &doc, int index)
{
    qint64 tick = 0;
    for (int i = 0; i < std::min(index, doc.frameCount()); ++i)
        tick += std::max(1, doc.frameAt(i).hold);
    return tick;
}

SoundController::SoundController(EditorState *state, PlaybackController *playback,
                                 QWidget *dialogParent, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_playback(playback)
    , m_dialogParent(dialogParent)
    , m_cache(new model::SoundCache(state->document(), this))
    , m_player(new SoundPlayer(state->document(), m_cache, this))
{
    m_import = new QAction(tr("Import Soun&d..."), this);
    m_import->setObjectName(QStringLiteral("file.importSound"));
    m_import->setToolTip(tr("Add a sound file to the soundtrack, starting at the current frame"));
    connect(m_import, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            m_dialogParent, tr("Import Sound"), QString(),
            tr("Sound files (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;All files (*)"));
        if (!path.isEmpty())
            importSound(path);
    });
    if (m_playback)
        m_playback->setClock(m_player);
    connect(m_player, &SoundPlayer::silent, this, &SoundController::message);
    // Said once for a burst: a document of 256 clips that cannot be played opens with one
    // message, not 256 in a row.
    auto *failures = new QTimer(this);
    failures->setSingleShot(true);
    failures->setInterval(200);
    auto failed = std::make_shared<QList<QPair<QString, QString>>>(); // name, why
    connect(m_cache, &model::SoundCache::soundFailed, this,
            [this, failures, failed](model::Id id, const QString &why) {
                const model::SoundClip *clip = m_state->document()->soundtrack().clip(id);
                if (clip && !why.isEmpty()) {
                    failed->append({clip->name, why});
                    failures->start();
                }
            });
    connect(failures, &QTimer::timeout, this, [this, failed] {
        if (failed->isEmpty())
            return;
        const auto &[name, why] = failed->front();
        if (failed->size() == 1)
            emit message(tr("The sound \"%1\" cannot be played: %2").arg(name, why));
        else
            emit message(
                tr("%n sound(s) cannot be played; \"%1\": %2", nullptr, int(failed->size()))
                    .arg(name, why));
        failed->clear();
    });
    connect(m_state, &EditorState::currentFrameChanged, this, &SoundController::frameShown);
}

void SoundController::frameShown(int index)
{
    if ((m_playback && m_playback->isPlaying()) || m_state->isPlaying())
        return;
    const model::Document &doc = *m_state->document();
    if (index < 0 || index >= doc.frameCount())
        return;
    m_player->playSlice(startTickOfFrame(doc, index), std::max(1, doc.frameAt(index).hold),
                        doc.settings().fps);
}

void SoundController::importSound(const QString &path)
{
    const QString name = QFileInfo(path).fileName();
    const QFileInfo info(path);
    const auto fail = [this, &name](const QString &why) {
        emit importFailed(tr("Cannot Import Sound"), tr("Cannot import \"%1\": %2").arg(name, why));
    };
    if (!info.isFile()) {
        fail(tr("it is not a file."));
        return;
    }
    if (info.size() > model::kMaxSoundClipBytes) {
        fail(tr("it is larger than %1 MB.").arg(model::kMaxSoundClipBytes >> 20));
        return;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        fail(file.errorString() + QLatin1Char('.'));
        return;
    }
    const QByteArray bytes = file.readAll();
    emit message(tr("Reading \"%1\"…").arg(name));
    const qint64 start = startTickOfFrame(*m_state->document(), m_state->currentFrameIndex());
    QPointer<SoundController> self(this);
    QThreadPool::globalInstance()->start([self, bytes, name, start] {
        auto decoded = model::decodeSound(bytes);
        model::DecodedSoundPtr sound;
        model::WaveformPtr waveform;
        QString error;
        if (decoded) {
            auto s = std::make_shared<model::DecodedSound>(std::move(*decoded));
            waveform = std::make_shared<const model::Waveform>(model::computeWaveform(*s));
            sound = std::move(s);
        } else {
            error = decoded.error();
        }
        if (!self)
            return;
        QMetaObject::invokeMethod(
            self.data(),
            [self, bytes, name, start, sound, waveform, error] {
                if (!self)
                    return;
                if (!sound) {
                    emit self->importFailed(
                        tr("Cannot Import Sound"),
                        tr("Cannot import \"%1\": %2 Nothing was changed.").arg(name, error));
                    return;
                }
                model::Document *doc = self->m_state->document();
                model::SoundClip clip;
                clip.name = name;
                clip.bytes = bytes;
                clip.start = std::min(start, model::kMaxSoundStart);
                auto *command = new model::AddSoundClipCommand(doc, clip);
                self->m_cache->insert(command->clipId(), sound, waveform, bytes.size());
                doc->undoStack()->push(command);
                emit self->importFinished(
                    command->clipId(),
                    tr("Imported \"%1\" (%2 s).").arg(name).arg(sound->seconds(), 0, 'f', 1));
                emit self->message(
                    tr("Imported \"%1\" (%2 s).").arg(name).arg(sound->seconds(), 0, 'f', 1));
            },
            Qt::QueuedConnection);
    });
}

void SoundController::setMuted(model::Id clipId, bool muted)
{
    model::Document *doc = m_state->document();
    if (auto command = model::soundClipMutedCommand(doc, clipId, muted))
        doc->undoStack()->push(command.release());
}

void SoundController::setVolume(model::Id clipId, double volume)
{
    model::Document *doc = m_state->document();
    if (auto command = model::soundClipVolumeCommand(doc, clipId, volume))
        doc->undoStack()->push(command.release());
}

void SoundController::askVolume(model::Id clipId)
{
    const model::SoundClip *clip = m_state->document()->soundtrack().clip(clipId);
    if (!clip)
        return;
    bool ok = false;
    const int percent = QInputDialog::getInt(
        m_dialogParent, tr("Sound Volume"), tr("Volume of \"%1\" (%):").arg(clip->name),
        int(std::lround(clip->volume * 100)), 0, int(model::kMaxSoundVolume * 100), 5, &ok);
    if (ok)
        setVolume(clipId, percent / 100.0);
}

void SoundController::remove(model::Id clipId)
{
    model::Document *doc = m_state->document();
    auto *command = new model::RemoveSoundClipCommand(doc, clipId);
    if (command->isObsolete()) {
        delete command;
        return;
    }
    doc->undoStack()->push(command);
}

void SoundController::move(model::Id clipId, qint64 start)
{
    model::Document *doc = m_state->document();
    if (auto command = model::moveSoundClipCommand(doc, clipId, start))
        doc->undoStack()->push(command.release());
}

} // namespace finbook::ui
