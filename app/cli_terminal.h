// The terminal side of the headless commands: whether a person is watching, and stopping
// cleanly when they press Ctrl+C (or the system asks the process to end).
#pragma once

namespace finbook::app {

bool stderrIsTerminal();
bool stdoutIsTerminal();

// From now on SIGINT, SIGTERM and SIGHUP only set a flag (interrupted()): the export polls it
// between steps, stops its encoder and removes its temporaries, then Finbook exits with
// 128 + the signal's number.
void catchInterrupts();
bool interrupted();
int interruptSignal(); // 0 when none arrived

} // namespace finbook::app
