#include "../command_text.h"

#include <finbook/geometry/erase/polyline_erase.h>
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/erase/stroke_cut.h>
#include <finbook/model/fill/fill_commands.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {

void dropRepeatedEnds(std::vector<StrokePoint> &points)
{
    const auto same = [](const StrokePoint &a, const StrokePoint &b) {
        return a.x == b.x && a.y == b.y;
    };
    if (points.size() > 1 && same(points[0], points[1]))
        points.erase(points.begin());
    if (points.size() > 1 && same(points[points.size() - 1], points[points.size() - 2]))
        points.pop_back();
}

// Whether the polyline is at least `least` long (stops counting there: pieces are long).
bool atLeast(const std::vector<StrokePoint> &points, double least)
{
    double sum = 0;
    for (std::size_t i = 1; i < points.size() && sum < least; ++i)
        sum += std::hypot(double(points[i].x - points[i - 1].x),
                          double(points[i].y - points[i - 1].y));
    return sum >= least;
}

} // namespace

std::optional<std::vector<StrokeDataPtr>> cutStroke(const StrokeData &stroke,
                                                    const std::vector<QPointF> &rub, double radius)
{
    const std::vector<StrokePoint> &points = stroke.points;
    if (points.empty() || rub.empty() || !std::isfinite(radius) || radius < 0)
        return std::nullopt;
    const double halfWidth = std::isfinite(stroke.width) ? std::max(0.0f, stroke.width) / 2 : 0;
    // Only the run of segments near the rub goes to the geometry: a rub touches a few dozen
    // points of a long stroke, and one mouse move must not copy all of them (bench: erase).
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for (const QPointF &p : rub)
        if (std::isfinite(p.x()) && std::isfinite(p.y())) {
            x0 = std::min(x0, p.x());
            x1 = std::max(x1, p.x());
            y0 = std::min(y0, p.y());
            y1 = std::max(y1, p.y());
        }
    const double pad = radius + halfWidth;
    x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
    const auto near = [&](std::size_t a, std::size_t b) {
        const StrokePoint &p = points[a], &q = points[b];
        return std::max(p.x, q.x) >= x0 && std::min(p.x, q.x) <= x1 && std::max(p.y, q.y) >= y0 &&
               std::min(p.y, q.y) <= y1;
    };
    const std::size_t segments = points.size() - 1;
    std::size_t first = points.size(), last = 0; // the window's first and last point
    for (std::size_t i = 0; i < std::max<std::size_t>(segments, 1); ++i)
        if (near(i, std::min(i + 1, segments))) {
            first = std::min(first, i);
            last = std::min(i + 1, segments);
        }
    if (first == points.size())
        return std::nullopt;
    const Eigen::Index n = Eigen::Index(last - first + 1);
    Eigen::MatrixX2d P(n, 2);
    Eigen::VectorXd reach(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const StrokePoint &p = points[first + std::size_t(i)];
        P.row(i) << p.x, p.y;
        reach(i) = halfWidth * std::clamp(double(p.pressure), 0.0, 1.0);
    }
    Eigen::MatrixX2d E(Eigen::Index(rub.size()), 2);
    for (std::size_t j = 0; j < rub.size(); ++j)
        E.row(Eigen::Index(j)) << rub[j].x(), rub[j].y();
    geometry::EraseResult erased = geometry::erasePolyline(P, reach, E, radius);
    if (!erased.touched)
        return std::nullopt;
    // Back to the whole stroke: the points outside the window are outside the rub's reach, so
    // a span that starts (ends) at the window's edge runs on to the stroke's start (end).
    for (geometry::KeptSpan &span : erased.kept) {
        span.from.segment += Eigen::Index(first);
        span.to.segment += Eigen::Index(first);
    }
    if (!erased.kept.empty() && segments > 0) {
        geometry::KeptSpan &head = erased.kept.front(), &tail = erased.kept.back();
        if (head.from == geometry::PolylinePlace{Eigen::Index(first), 0.0})
            head.from = {0, 0.0};
        if (tail.to == geometry::PolylinePlace{Eigen::Index(last) - 1, 1.0})
            tail.to = {Eigen::Index(segments) - 1, 1.0};
    }
    std::vector<StrokeDataPtr> pieces;
    for (const geometry::KeptSpan &span : erased.kept) {
        auto piece = std::make_shared<StrokeData>();
        piece->color = stroke.color;
        piece->width = stroke.width;
        piece->points.reserve(std::size_t(span.to.segment - span.from.segment) + 2);
        piece->points.push_back(pointAlong(points, span.from));
        piece->points.insert(piece->points.end(),
                             points.begin() + std::ptrdiff_t(span.from.segment) + 1,
                             points.begin() + std::ptrdiff_t(span.to.segment) + 1);
        piece->points.push_back(pointAlong(points, span.to));
        // A cut exactly on a sample point repeats it (only the cut ends can).
        dropRepeatedEnds(piece->points);
        if (atLeast(piece->points, kMinPieceLength))
            pieces.push_back(std::move(piece));
    }
    return pieces;
}

StrokePoint pointAlong(const std::vector<StrokePoint> &points, const geometry::PolylinePlace &at)
{
    const StrokePoint &a = points[std::size_t(at.segment)];
    if (points.size() == 1 || at.t == 0.0)
        return a;
    const StrokePoint &b = points[std::size_t(at.segment) + 1];
    if (at.t == 1.0)
        return b; // exactly: a + 1 × (b − a) is not always b in floating point
    const float t = float(at.t);
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y),
            a.pressure + t * (b.pressure - a.pressure)};
}

std::vector<Id> pushStrokeCut(Document *doc, Id strokeId, const std::vector<StrokeDataPtr> &pieces)
{
    const StrokeLocation at = doc->locateStroke(strokeId);
    if (!at.isValid())
        return {};
    const StrokeGroup &group = doc->frameAt(at).groups[std::size_t(at.group)];
    const Id groupId = group.id;
    std::vector<Fill> fills = group.fills;
    QUndoStack *stack = doc->undoStack();
    stack->push(new RemoveStrokeCommand(doc, strokeId));
    std::vector<Id> ids;
    int index = at.stroke;
    for (const StrokeDataPtr &piece : pieces) {
        auto *add = new AddStrokeCommand(doc, groupId, piece, index++);
        ids.push_back(add->strokeId());
        stack->push(add);
    }
    bool named = false;
    for (Fill &fill : fills)
        forEachFillStrokes(fill, [&](std::vector<Id> &strokes) {
            const auto it = std::lower_bound(strokes.begin(), strokes.end(), strokeId);
            if (it == strokes.end() || *it != strokeId)
                return;
            named = true;
            strokes.erase(it);
            strokes.insert(strokes.end(), ids.begin(), ids.end());
            std::sort(strokes.begin(), strokes.end());
            strokes.erase(std::unique(strokes.begin(), strokes.end()), strokes.end());
        });
    if (named)
        stack->push(new SetFillsCommand(doc, groupId, std::move(fills),
                                        Command::tr("Keep Fills Along a Cut")));
    return ids;
}

} // namespace finbook::model
