// One export at a time per target, and the cleaning up after killed ones.
#pragma once

#include <QString>

#include <memory>

class QLockFile;

namespace finbook::model {

// One export at a time per target: a lock file beside a file target (".NAME.export-lock") or
// inside a sequence's folder (".finbook-export.lock"), removed on destruction. A lock whose
// process is gone (killed) is taken over. While it is held, the temporaries of earlier
// exports to the same target (".NAME.XXXXXX.part", ".finbook-export-XXXXXX/") can only be
// leftovers of killed exports: removeLeftovers() deletes them, after finishing the swap a
// killed sequence export had begun (finishInterruptedSwap).
class TargetLock {
public:
    TargetLock(const QString &target, bool folder);
    ~TargetLock();
    TargetLock(const TargetLock &) = delete;
    TargetLock &operator=(const TargetLock &) = delete;
    bool tryLock();
    void removeLeftovers() const;

private:
    QString m_target;
    bool m_folder;
    std::unique_ptr<QLockFile> m_lock;
};

} // namespace finbook::model
