// The command line: `finbook info FILE`, `finbook export FILE OUTDIR`, and the options the
// editor takes. Everything here works without a display.
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace finbook::app {

enum class ExitCode { Ok = 0, Failure = 1, BadInput = 2 };

// True when the arguments ask for a headless subcommand (so no window system is needed).
bool isHeadlessCommand(const QStringList &arguments);

// Runs `info` or `export`. `arguments` excludes the program name. Messages go to `err` as
// one line; results (JSON, file list) go to `out`.
int runHeadlessCommand(const QStringList &arguments, QTextStream &out, QTextStream &err);

// `finbook info` as a JSON object: format version, frames, objects, strokes, points.
QByteArray documentInfoJson(const QString &path, QString *error);

} // namespace finbook::app
