// Export targets whose names are not valid in the file name encoding (Latin-1 names on an
// old disk, say), as given on the command line: the export writes exactly those bytes.
//
// Qt would decode such a name as UTF-8 and write U+FFFD in place of the bad bytes: another
// name. So a folder on the way named by such bytes is made (when missing) and opened here by
// its bytes, and Qt reaches it and everything in it through /proc/PID/fd/N; a file so named
// gets its bytes as ExportOptions::nativeName, for the export's last step, a rename by bytes
// (its temporaries and its lock use valid names beside it). Valid names pass unchanged.
#pragma once

#include <finbook/model/export/export_options.h>

#include <QByteArray>
#include <QString>

#include <vector>

namespace finbook::app {

class NativeTarget {
public:
    NativeTarget() = default;
    ~NativeTarget(); // closes the folders; removes those made here unless kept, when empty
    NativeTarget(const NativeTarget &) = delete;
    NativeTarget &operator=(const NativeTarget &) = delete;

    // Points options.target (and options.nativeName) at the target named by `bytes`, a file
    // or, with `folder`, the folder of a sequence. False with `*reason` when a folder on the
    // way cannot be made or opened.
    bool prepare(const QByteArray &bytes, bool folder, model::ExportOptions &options,
                 QString *reason);
    void keep() { m_created.clear(); } // the export succeeded: its folders stay

    // `text` (a message, a path the export reported) with the folders opened here named as
    // given (the bytes decoded, U+FFFD for the bad ones).
    QString shown(const QString &text) const;
    // The bytes naming `path`, a path the export reported.
    QByteArray bytes(const QString &path) const;

private:
    QString openFolder(const QByteArray &bytes, QString *reason);

    struct Alias {
        QString path;     // /proc/PID/fd/N
        QByteArray bytes; // the folder as given
    };
    std::vector<Alias> m_aliases;
    std::vector<int> m_descriptors;
    std::vector<QByteArray> m_created; // deepest last
    QString m_file;                    // a file target with a native name, and its bytes
    QByteArray m_fileBytes;
};

// Whether `bytes` come back unchanged from their decoded name.
bool isValidFileName(const QByteArray &bytes);

} // namespace finbook::app
