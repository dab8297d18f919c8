// SVG references, rendered at a bounded cost. Qt's SVG renderer has no limits of its own: a
// small file can ask for millions of elements (<use> of <use>), a picture 16,384 px a side, or
// minutes of painting, and text in it reaches the font database, which aborts the process
// where no QGuiApplication exists (`finbook export` used a QCoreApplication). Private to the
// model: reference_media.cpp calls it for every picture that is SVG.
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace finbook::model::reference_detail {

constexpr int kMaxSvgSide = 4096;            // rendered pixels a side, at most (scaled to fit)
constexpr qint64 kMaxSvgElements = 100000;   // after <use> is expanded
constexpr qint64 kMaxSvgBytes = 16ll << 20;  // of XML, after an .svgz is decompressed
constexpr double kMaxSvgRenderSeconds = 2.0; // of CPU time spent painting one picture

// Whether `bytes` look like an SVG document (plain or gzip-compressed): they are then for
// renderSvg() alone, never for another decoder (FFmpeg's would render them without limits).
bool looksLikeSvg(const QByteArray &bytes);

// The SVG rendered at its own size scaled to fit kMaxSvgSide, painted band by band so that
// the time spent is checked as it goes. Null with `error` set (one sentence) when it is not
// valid SVG, passes a limit above, or there is no QGuiApplication to render its text with.
// `budget` (optional) is CPU seconds left for the pictures of one sequence (ReferenceMedia
// gives each sequence 10 s): the time spent is
// taken from it, and none is spent once it is gone (a sequence of slow SVGs, each within its
// own limit, would otherwise multiply it by its length).
QImage renderSvg(const QByteArray &bytes, QString *error, double *budget = nullptr);

} // namespace finbook::model::reference_detail
