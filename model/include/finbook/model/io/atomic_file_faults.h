// Test seam of writeFileAtomically (io/atomic_file.h): each step that can fail on a real disk
// asks a process-wide hook first. The hook returns an errno to make that step fail as the
// system call would (or ends the process there, to play a kill), 0 to let it run. Tests only;
// nothing else sets it.
#pragma once

#include <functional>

namespace finbook::model {

enum class AtomicStep {
    CreateTemporary, // open(O_CREAT | O_EXCL) of the temporary file beside the target
    SyncTemporary,   // fsync of the written temporary file
    CloseTemporary,  // its close
    LinkBackup,      // link() of the current file to a temporary name beside the backup
    CopyBackup,      // where links fail: the copy of the current file made instead
    ReplaceTarget,   // rename() of the temporary file over the target
    ReplaceBackup,   // rename() of the kept current file over the backup
    RestoreTarget,   // rename() back of the kept file when the backup could not be replaced
};

using AtomicFaultHook = std::function<int(AtomicStep)>;

// Installs `hook` (empty: none) and returns the previous one.
AtomicFaultHook setAtomicFaultHook(AtomicFaultHook hook);

} // namespace finbook::model
