// `finbook export`: one or more .finbook files to PNG/SVG sequences, GIF, MP4, WebM, APNG, an
// HTML flipbook, or one frame as a 3D model (OBJ + MTL, or glTF binary).
//
//   finbook export FILE OUT                 format from OUT's suffix (.gif .mp4 .webm .apng
//                                           .html .obj .glb), or a folder of PNGs when OUT has none
//   finbook export FILE... --out-dir DIR    each FILE to DIR/<name>.<suffix> (DIR/<name>/ for
//                                           sequences)
//   options: --format F, --range A-B, --frame N, --scale S, --fps N, --transparent,
//            --background COLOR, --one-per-drawing, --overwrite
#pragma once

#include <QCommandLineParser>
#include <QStringList>

class QTextStream;

namespace finbook::app {

// Adds the export options to the editor's command-line parser (main.cpp), so they are known
// and listed by --help.
void addExportOptions(QCommandLineParser &parser);
// The export options that were given, as "--name=value" (or "--flag") words for
// runHeadlessCommand.
QStringList exportOptionArguments(const QCommandLineParser &parser);

// `arguments` are what follows "export": input files, the output, and "--name=value" option
// words. Prints the files written (one per line) on `out`. Progress goes to stderr only when
// stderr is a terminal. Exit codes: 0 done; 2 bad arguments, unreadable input or a file in the
// way without --overwrite; 1 the output could not be made (disk, ffmpeg). Errors are one line.
int runExportCommand(const QStringList &arguments, QTextStream &out, QTextStream &err);

} // namespace finbook::app
