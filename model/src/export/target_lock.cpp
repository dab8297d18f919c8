#include "target_lock.h"

#include "pending_output.h"

#include <QDir>
#include <QFileInfo>
#include <QLockFile>

namespace finbook::model {

namespace {
// QTemporaryFile and QTemporaryDir replace "XXXXXX" by six letters or digits.
bool isRandomPart(QStringView text)
{
    if (text.size() != 6)
        return false;
    for (const QChar c : text)
        if (!(c.isLetterOrNumber() && c.unicode() < 128))
            return false;
    return true;
}

// Names compared as text, never as a pattern: a target named "a[1].gif" is no wildcard.
bool isLeftoverOf(const QString &entry, const QString &prefix, const QString &suffix)
{
    return entry.size() == prefix.size() + 6 + suffix.size() && entry.startsWith(prefix) &&
           entry.endsWith(suffix) && isRandomPart(QStringView(entry).mid(prefix.size(), 6));
}
} // namespace

TargetLock::TargetLock(const QString &target, bool folder)
    : m_target(target)
    , m_folder(folder)
{}

TargetLock::~TargetLock() = default; // QLockFile removes its file

bool TargetLock::tryLock()
{
    const QFileInfo info(m_target);
    const QString path =
        m_folder ? QDir(m_target).filePath(QStringLiteral(".finbook-export.lock"))
                 : info.dir().filePath(QStringLiteral(".%1.export-lock").arg(info.fileName()));
    m_lock = std::make_unique<QLockFile>(path);
    // Only a dead owner makes the lock stale: an export may run for hours.
    m_lock->setStaleLockTime(0);
    return m_lock->tryLock(0);
}

void TargetLock::removeLeftovers() const
{
    if (!m_lock || !m_lock->isLocked())
        return;
    const QFileInfo info(m_target);
    const QDir dir = m_folder ? QDir(m_target) : info.dir();
    const QString prefix =
        m_folder ? QStringLiteral(".finbook-export-") : QStringLiteral(".%1.").arg(info.fileName());
    const QString suffix = m_folder ? QString() : QStringLiteral(".part");
    // A file target's leftovers are files, and folders (a GIF's drawings, export_encoded.cpp).
    const QDir::Filters filter = (m_folder ? QDir::Dirs : QDir::Files | QDir::Dirs) | QDir::Hidden |
                                 QDir::NoDotAndDotDot | QDir::System;
    for (const QString &entry : dir.entryList(filter)) {
        if (!isLeftoverOf(entry, prefix, suffix))
            continue;
        const QString path = dir.filePath(entry);
        if (QFileInfo(path).isSymLink()) {
            QFile::remove(path);
        } else if (m_folder) {
            // A swap the kill interrupted is finished first: the folder gets back all of its
            // old files, or keeps all of the new ones (pending_output.h).
            finishInterruptedSwap(m_target, path);
            QDir(path).removeRecursively();
        } else if (QFileInfo(path).isDir()) {
            QDir(path).removeRecursively();
        } else {
            QFile::remove(path);
        }
    }
}

} // namespace finbook::model
