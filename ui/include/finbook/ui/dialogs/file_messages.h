// What a person reads when a .finbook file will not open: what happened, in an animator's
// words, and what to do ("The file is damaged near the end: it looks cut off."). The
// loader's technical sentence (byte offsets, field names) goes under "Show Details". The
// backup Finbook keeps beside a saved file ("walk.finbook~") is named only when it exists.
#pragma once

#include <finbook/model/finbook_file.h>

#include <QCoreApplication>
#include <QString>

namespace finbook::ui {

struct FileProblem {
    QString text;    // for the message box: one to three short sentences
    QString details; // for "Show Details": the loader's message and the full path
};

class FileMessages {
    Q_DECLARE_TR_FUNCTIONS(FileMessages)
public:
    // Needs the path that failed and the loader's error; looks at the disk (does the file,
    // does its backup exist) but never changes it.
    static FileProblem openProblem(const QString &path, const model::FileError &error);

private:
    static QString reason(const QString &path, const model::FileError &error, bool *backupHelps);
};

} // namespace finbook::ui
