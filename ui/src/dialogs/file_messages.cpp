#include <finbook/ui/dialogs/file_messages.h>

#include <QDir>
#include <QFileInfo>

namespace finbook::ui {

using model::FileErrorCode;

QString FileMessages::reason(const QString &path, const model::FileError &error, bool *backupHelps)
{
    const QFileInfo info(path);
    *backupHelps = true;
    switch (error.code) {
    case FileErrorCode::OpenFailed:
        if (!info.exists())
            return tr("The file is not there any more: it may have been moved, renamed or "
                      "deleted.");
        *backupHelps = false;
        if (info.isDir())
            return tr("This is a folder, not an animation. Choose a file ending in .finbook.");
        if (!info.isFile())
            return tr("This is a device or a pipe, not an animation. Choose a file ending in "
                      ".finbook.");
        if (!info.isReadable())
            return tr("You are not allowed to read this file. Ask whoever owns it to share it "
                      "with you, or open a copy of it.");
        *backupHelps = true;
        return tr("The disk could not read the file. If it is on a removable drive or a "
                  "network folder, check that it is still connected.");
    case FileErrorCode::NotFinbook:
        if (info.size() == 0)
            return tr("The file is empty: there is no drawing in it.");
        return tr("This is not a Finbook animation. Choose a file ending in .finbook.");
    case FileErrorCode::NewerVersion:
        *backupHelps = false;
        return tr("It was saved by a newer version of Finbook. Install that version to open "
                  "it.");
    case FileErrorCode::Truncated:
        return tr("The file is damaged near the end: it looks cut off. Perhaps a copy or a "
                  "save was interrupted.");
    case FileErrorCode::TooLarge:
        return tr("The file is damaged, or too large for this computer: it asks for more "
                  "memory than Finbook can use.");
    case FileErrorCode::Damaged:
        return tr("The file is damaged: some of it changed after it was saved. Finbook can "
                  "open what is still readable.");
    case FileErrorCode::OutOfMemory:
        *backupHelps = false;
        return tr("This computer has not enough free memory to open the file. Close other "
                  "programs or documents and try again.");
    case FileErrorCode::BadValue:
    case FileErrorCode::WriteFailed:
    case FileErrorCode::DiskFull:
        break;
    }
    return tr("The file is damaged: part of it cannot be read.");
}

FileProblem FileMessages::openProblem(const QString &path, const model::FileError &error)
{
    const QString name = QFileInfo(path).fileName();
    bool backupHelps = false;
    QStringList text{tr("Finbook cannot open \u201c%1\u201d.").arg(name),
                     reason(path, error, &backupHelps)};
    const QFileInfo backup(model::finbookBackupPath(path));
    if (backupHelps && backup.isFile())
        text << tr("Finbook kept the version saved before it as \u201c%1\u201d in the same "
                   "folder: open that one to get your work back.")
                    .arg(backup.fileName());
    FileProblem problem;
    problem.text = text.join(QLatin1Char(' '));
    problem.details = error.message + QStringLiteral("\n\n") + QDir::toNativeSeparators(path);
    return problem;
}

} // namespace finbook::ui
