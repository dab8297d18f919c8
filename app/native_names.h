// File names given on the command line that are not valid UTF-8 (Latin-1 names on an old
// disk, say). Qt decodes every file name as UTF-8 and would replace the bad bytes by U+FFFD,
// naming another file: such an input is opened by its original bytes instead, and such an
// output is written under its original bytes (native_target.h).
#pragma once

#include <QByteArray>
#include <QString>

namespace finbook::app {

// Keeps the bytes of the arguments whose text would not give them back. Call once, first.
void rememberRawArguments(int argc, char **argv);

// The bytes `argument` came from: the original ones for a lossy argument.
QByteArray argumentBytes(const QString &argument);

// A path Qt can open for the file `argument` names: the argument itself, or for a lossy one
// /proc/self/fd/N of the file opened by its original bytes.
QString openablePath(const QString &argument);

} // namespace finbook::app
