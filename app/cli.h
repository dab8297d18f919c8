// The command line: `finbook info FILE`, `finbook export FILE OUT` (cli_export.h), and the options
// the editor takes. Everything here works without a display.
#pragma once

#include <QString>
#include <QStringList>
#include <QtGlobal>

class QTextStream;

namespace finbook::app {

enum class ExitCode { Ok = 0, Failure = 1, BadInput = 2 };

// True when the arguments ask for a headless subcommand (so no window system is needed).
bool isHeadlessCommand(const QStringList &arguments);

// True when the headless command may draw text (an export that includes the reference, which
// may be an SVG with text): it then needs a QGuiApplication (on the offscreen platform).
bool headlessCommandRendersText(const QStringList &arguments);

// A Qt message handler for the headless commands: their contract is their own one line on
// stderr, so Qt's warnings (a platform plugin's, fontconfig's) are dropped; fatal ones are
// printed.
void quietQtMessages(QtMsgType type, const QMessageLogContext &context, const QString &message);

// Runs `info` or `export`. `arguments` are the positional arguments (options already parsed
// away), starting with the command; `export` also takes its options here as "--name=value"
// words (see cli_export.h). A failure is one line on `err` and exit code 2 for bad
// input (missing or damaged file, wrong arguments) or 1 when the output cannot be written;
// results (JSON, the exported file names) go to `out`.
int runHeadlessCommand(const QStringList &arguments, QTextStream &out, QTextStream &err);

// `finbook info` as a one-line JSON object: format_version, frames, objects, strokes,
// points, stroke_data (distinct stored strokes), pins, fps, canvas_width, canvas_height,
// ticks (playback ticks of the play range, holds included) and duration_s (ticks / fps).
QByteArray documentInfoJson(const QString &path, QString *error);

// The version printed by `finbook --version` (the project version CMake was given).
QString finbookVersion();

} // namespace finbook::app
