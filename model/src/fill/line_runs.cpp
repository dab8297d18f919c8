// A cut-out pose's lines cut into what shows and what is hidden (line_runs.h).
#include "line_runs.h"

#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace finbook::model::line_runs {

namespace {

// Bisection steps for where a segment enters or leaves hiding: 2⁻¹⁴ of a segment a few px
// long is far below what a pen shows.
constexpr int kCrossingSteps = 14;
// A segment is looked at this often (px) along its length for where it enters or leaves
// hiding, at most kMostSamples times (a corrupt file's segment may be kilometres long).
constexpr double kSampleStep = 2.0;
constexpr int kMostSamples = 4096;

// How far past a line's half width (px) its sides are looked at, and at how many points round
// it.
constexpr double kSideReach = 1.0;
constexpr int kRound = 8;

StrokePoint lerp(const StrokePoint &a, const StrokePoint &b, double t)
{
    const auto mix = [t](float u, float v) { return float(u + (v - u) * t); };
    return {mix(a.x, b.x), mix(a.y, b.y), mix(a.pressure, b.pressure)};
}

QPointF at(const StrokePoint &p)
{
    return {p.x, p.y};
}

} // namespace

std::vector<Piece> piecesOf(const std::vector<Segment> &segments)
{
    std::vector<Piece> pieces;
    pieces.reserve(segments.size());
    for (const Segment &segment : segments)
        pieces.push_back({segment, Hidden::No});
    return pieces;
}

std::vector<Piece> cutWhere(const std::vector<Piece> &pieces, const Hides &hides, Hidden kind)
{
    std::vector<Piece> out;
    out.reserve(pieces.size());
    for (const Piece &piece : pieces) {
        if (piece.hidden != Hidden::No) {
            out.push_back(piece);
            continue;
        }
        const Segment &s = piece.segment;
        // Looked at every kSampleStep px, not only at the ends: a segment drawn long and
        // straight (a chord across a cut, a sketch's simplified line) may pass under a piece
        // in its middle only.
        const double length = std::hypot(double(s.b.x - s.a.x), double(s.b.y - s.a.y));
        const int samples = std::clamp(int(std::ceil(length / kSampleStep)), 1, kMostSamples);
        double from = 0.0; // where the current part begins
        bool hidden = hides(s, at(s.a));
        double last = 0.0;
        for (int k = 1; k <= samples; ++k) {
            const double t = double(k) / samples;
            const bool now = hides(s, at(k == samples ? s.b : lerp(s.a, s.b, t)));
            if (now != hidden) {
                // Where it changes lies between the last two samples.
                double same = last, other = t;
                for (int step = 0; step < kCrossingSteps; ++step) {
                    const double mid = 0.5 * (same + other);
                    (hides(s, at(lerp(s.a, s.b, mid))) == hidden ? same : other) = mid;
                }
                Segment part = s;
                part.a = from == 0.0 ? s.a : lerp(s.a, s.b, from);
                part.b = lerp(s.a, s.b, same);
                out.push_back({part, hidden ? kind : Hidden::No});
                from = same;
                hidden = now;
            }
            last = t;
        }
        Segment part = s;
        if (from != 0.0)
            part.a = lerp(s.a, s.b, from);
        out.push_back({part, hidden ? kind : Hidden::No});
    }
    return out;
}

std::vector<Run> runsOf(const std::vector<Piece> &pieces)
{
    // Consecutive segments share their ends, so a run takes each segment's start only when it
    // begins there (points repeated in the stroke stay as drawn).
    std::vector<Run> runs;
    Run run;
    for (const Piece &piece : pieces) {
        if (!run.points.empty() && run.hidden != piece.hidden) {
            const StrokePoint last = run.points.back();
            if (run.points.size() >= 2)
                runs.push_back(std::move(run));
            run.points = {last};
        }
        run.hidden = piece.hidden;
        if (run.points.empty())
            run.points.push_back(piece.segment.a);
        run.points.push_back(piece.segment.b);
    }
    if (run.points.size() >= 2)
        runs.push_back(std::move(run));
    return runs;
}

std::vector<Run> withoutSlivers(std::vector<Run> runs, double shortest)
{
    for (Run &run : runs) {
        double length = 0.0;
        for (std::size_t k = 1; k < run.points.size() && length < shortest; ++k)
            length += std::hypot(double(run.points[k].x - run.points[k - 1].x),
                                 double(run.points[k].y - run.points[k - 1].y));
        if (run.hidden == Hidden::Covered && length < shortest)
            run.hidden = Hidden::No;
    }
    std::vector<Run> joined;
    for (Run &run : runs) {
        if (!joined.empty() && joined.back().hidden == run.hidden && !run.points.empty()) {
            std::vector<StrokePoint> &points = joined.back().points;
            points.insert(points.end(), run.points.begin() + 1, run.points.end());
            continue;
        }
        joined.push_back(std::move(run));
    }
    return joined;
}

FillRaster::FillRaster(const std::vector<const FillItem *> &items)
{
    QRectF bounds;
    for (const FillItem *item : items)
        bounds |= item->path.controlPointRect();
    if (items.empty() || !bounds.isValid() || !std::isfinite(bounds.width()) ||
        !std::isfinite(bounds.height()))
        return;
    // A px per canvas px, fewer for a drawing beyond kMostPixels.
    m_scale =
        std::min(1.0, std::sqrt(kMostPixels / std::max(1.0, bounds.width() * bounds.height())));
    m_origin = bounds.topLeft();
    const int w = int(std::ceil(bounds.width() * m_scale)) + 1;
    const int h = int(std::ceil(bounds.height() * m_scale)) + 1;
    m_image = QImage(w, h, QImage::Format_RGB32);
    m_image.fill(0);
    QPainter painter(&m_image);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    painter.scale(m_scale, m_scale);
    painter.translate(-m_origin);
    for (const FillItem *item : items)
        painter.fillPath(item->path, QColor::fromRgb(QRgb(item->fill + 1)));
}

int FillRaster::at(QPointF p) const
{
    const double x = std::floor((p.x() - m_origin.x()) * m_scale);
    const double y = std::floor((p.y() - m_origin.y()) * m_scale);
    if (m_image.isNull() || !(x >= 0.0 && y >= 0.0 && x < m_image.width() && y < m_image.height()))
        return -1;
    const QRgb value = reinterpret_cast<const QRgb *>(m_image.constScanLine(int(y)))[int(x)];
    return int(value & 0xffffffu) - 1;
}

namespace {
// The items of `layers` with a fill index, in the order they are painted.
std::vector<const FillItem *> indexed(const std::vector<PaintLayer> &layers)
{
    std::vector<const FillItem *> out;
    for (const PaintLayer &layer : layers)
        for (const FillItem &item : layer.fills)
            if (item.fill >= 0 && item.fill < 0xfffffe)
                out.push_back(&item);
    return out;
}

std::vector<const FillItem *> indexed(const std::vector<FillItem> &items)
{
    std::vector<const FillItem *> out;
    for (const FillItem &item : items)
        if (item.fill >= 0 && item.fill < 0xfffffe)
            out.push_back(&item);
    return out;
}
} // namespace

bool movedApart(const QTransform &a, const QTransform &b)
{
    const double worst =
        std::max({std::abs(a.m11() - b.m11()), std::abs(a.m12() - b.m12()),
                  std::abs(a.m21() - b.m21()), std::abs(a.m22() - b.m22()),
                  std::abs(a.dx() - b.dx()) * 1e-3, std::abs(a.dy() - b.dy()) * 1e-3});
    return !(worst < 1e-6);
}

MergedLines::MergedLines(const StrokeGroup &group, const std::vector<PaintLayer> &layers,
                         const std::vector<FillItem> &rest)
{
    const DeformedStrokes *posed = group.deformed.get();
    if (!posed || posed->pieces.empty() || rest.empty() || posed->motions.size() != layers.size())
        return;
    m_back.resize(layers.size());
    for (std::size_t layer = 0; layer < layers.size(); ++layer) {
        if (!posed->motions[layer])
            continue;
        bool invertible = false;
        const QTransform back = posed->motions[layer]->inverted(&invertible);
        if (invertible)
            m_back[layer] = back;
    }
    // Only a piece that moved against another can lay a line inside a fill (at rest, or all
    // moved as one, each line bounds what it bounded).
    for (std::size_t layer = 1; layer < layers.size() && !m_any; ++layer)
        m_any = m_back[layer] && (!m_back[0] || movedApart(*m_back[layer], *m_back[0]));
    if (!m_any)
        return;
    // A line of the roots' piece can lie so only where a cut piece or a socket lies round it.
    for (const QPainterPath &piece : posed->pieces)
        m_near.push_back(piece.controlPointRect());
    for (const QPainterPath &socket : posed->sockets)
        if (!socket.isEmpty())
            m_near.push_back(socket.controlPointRect());
    m_shown = FillRaster(indexed(layers));
    m_rest = FillRaster(indexed(rest));
}

bool MergedLines::hides(std::size_t layer, QPointF p, double width, bool seam) const
{
    if (!m_any || layer >= m_back.size() || !m_back[layer])
        return false;
    const double reach =
        0.5 * (std::isfinite(width) ? std::clamp(width, 0.0, 64.0) : 1.0) + kSideReach;
    if (layer == 0 && std::none_of(m_near.begin(), m_near.end(), [&](const QRectF &near) {
            return near.adjusted(-reach, -reach, reach, reach).contains(p);
        }))
        return false;
    // Round the point rather than either side of the line: a traced outline's stair steps
    // turn each segment's own direction across the line.
    std::array<QPointF, kRound> round;
    for (int k = 0; k < kRound; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kRound;
        round[std::size_t(k)] = QPointF(std::cos(angle), std::sin(angle)) * reach;
    }
    const int shown = m_shown.at(p + round[0]);
    if (shown < 0)
        return false;
    for (std::size_t k = 1; k < round.size(); ++k)
        if (m_shown.at(p + round[k]) != shown)
            return false;
    if (seam)
        return true;
    // At rest the line was that fill's edge: round it, the fill on one side and no fill on the
    // other. (A line between it and another fill stays: left out, the two would be one region
    // once the pose is applied.)
    const QTransform &back = *m_back[layer];
    bool in = false, out = false;
    for (const QPointF &offset : round) {
        const int fill = m_rest.at(back.map(p + offset));
        in = in || fill == shown;
        out = out || fill < 0;
    }
    return in && out;
}

} // namespace finbook::model::line_runs
