// The hidden parts of lines that an edit uncovers (uncovered_lines.h).
#include "../command_text.h"

#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/erase/stroke_cut.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/fill/uncovered_lines.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace finbook::model {

namespace {

// Samples along a hidden part: at most this far apart (canvas px), so that a long straight
// segment half under a fill is seen in its middle too.
constexpr double kUncoverStep = 2.0;
// A run shorter than this many pen widths takes the state of the runs beside it: the ends of a
// hidden part lie on the outline that covered it, where inside and outside are a rounding apart.
constexpr double kShortestUncoveredRun = 2.0;
// The most samples one part is given (a part crossing a whole canvas at kUncoverStep).
constexpr int kMostUncoverSamples = 8192;

std::vector<geometry::PolylinePlace> runSamples(const std::vector<StrokePoint> &points)
{
    std::vector<geometry::PolylinePlace> out;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const double length = std::hypot(double(points[k + 1].x) - double(points[k].x),
                                         double(points[k + 1].y) - double(points[k].y));
        const int n = std::clamp(int(std::ceil(length / kUncoverStep)), 1, kMostUncoverSamples);
        for (int j = 0; j < n; ++j)
            out.push_back({Eigen::Index(k), double(j) / double(n)});
        if (out.size() > std::size_t(kMostUncoverSamples))
            return {};
    }
    out.push_back({Eigen::Index(points.size()) - 1, 0.0});
    return out;
}

// The fills of `group` as shown, for "is this place of a line covered".
struct FillCover {
    std::vector<QPainterPath> paths;
    std::vector<QRectF> boxes;
    // Of the fills whose `only` is true (all when `only` is empty).
    FillCover(const StrokeGroup &group, double closeGap, const std::vector<char> &only = {})
    {
        for (FillItem &item : fillList(group, closeGap)) {
            if (!only.empty() && (item.fill < 0 || std::size_t(item.fill) >= only.size() ||
                                  !only[std::size_t(item.fill)]))
                continue;
            boxes.push_back(item.path.boundingRect());
            paths.push_back(std::move(item.path));
        }
    }
    bool covers(QPointF q) const
    {
        for (std::size_t i = 0; i < paths.size(); ++i)
            if (boxes[i].contains(q) && paths[i].contains(q))
                return true;
        return false;
    }
    // Whether fills cover the line at `at` on both sides, a pen width off it (a part that lies
    // along the edge of a fill is not under it).
    bool covers(const std::vector<StrokePoint> &points, const geometry::PolylinePlace &at,
                double width) const
    {
        const std::size_t k = std::min(std::size_t(at.segment), points.size() - 2);
        const StrokePoint p = pointAlong(points, at);
        const double dx = double(points[k + 1].x) - double(points[k].x);
        const double dy = double(points[k + 1].y) - double(points[k].y);
        const double length = std::hypot(dx, dy);
        if (!(length > 0.0))
            return covers(QPointF(p.x, p.y));
        const double off = std::max(width, 1.0) / length;
        const QPointF n(-dy * off, dx * off);
        return covers(QPointF(p.x, p.y) + n) && covers(QPointF(p.x, p.y) - n);
    }
};

bool isHiddenPart(const Stroke &s)
{
    return s.data && s.data->color == kHiddenLineColor && s.data->points.size() >= 2;
}

// A hidden part of `after` that the edit may have uncovered: its samples, which of them to ink,
// and the colour of its line's inked parts.
struct HiddenCandidate {
    std::size_t index = 0; // into after.strokes
    std::vector<geometry::PolylinePlace> places;
    std::vector<char> uncovered; // the runs to ink, smoothed
    QRgb ink = 0xff000000;
};

// Runs shorter than kShortestUncoveredRun pen widths take the state of the runs beside them.
void smoothRuns(std::vector<char> &state, const std::vector<StrokePoint> &points,
                const std::vector<geometry::PolylinePlace> &places, double width)
{
    const double shortest = kShortestUncoveredRun * std::max(width, 0.5);
    for (int pass = 0; pass < 2; ++pass) {
        struct Run {
            std::size_t from, to; // samples [from, to]
            double length;
        };
        std::vector<Run> runs;
        for (std::size_t i = 0; i < state.size();) {
            std::size_t j = i;
            double length = 0.0;
            while (j + 1 < state.size() && state[j + 1] == state[i]) {
                const StrokePoint a = pointAlong(points, places[j]),
                                  b = pointAlong(points, places[j + 1]);
                length += std::hypot(double(b.x) - double(a.x), double(b.y) - double(a.y));
                ++j;
            }
            runs.push_back({i, j, length});
            i = j + 1;
        }
        if (runs.size() < 2)
            return;
        bool changed = false;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            if (runs[r].length >= shortest)
                continue;
            const bool before = r > 0, after = r + 1 < runs.size();
            const char to = before ? state[runs[r - 1].from] : state[runs[r + 1].from];
            if (before && after && state[runs[r - 1].from] != state[runs[r + 1].from])
                continue; // between two states: it stays as it is
            // A short run at an end of the part is inked only if it is (the part's end lies on
            // the outline that hid it, and a run inked past it would poke into the next fill).
            if ((!before || !after) && to)
                continue;
            for (std::size_t i = runs[r].from; i <= runs[r].to; ++i)
                state[i] = to;
            changed = true;
        }
        if (!changed)
            return;
    }
}

// The pieces of a part: its uncovered runs inked, the rest hidden, each beginning where the
// one before ends.
std::vector<StrokeDataPtr> piecesOfPart(const StrokeData &part, const HiddenCandidate &c)
{
    std::vector<StrokeDataPtr> out;
    std::size_t i = 0;
    while (i < c.places.size()) {
        std::size_t j = i;
        while (j + 1 < c.places.size() && c.uncovered[j + 1] == c.uncovered[i])
            ++j;
        // The piece runs from sample i to the first sample of the next run (shared end).
        const std::size_t last = std::min(j + 1, c.places.size() - 1);
        auto piece = std::make_shared<StrokeData>(part);
        piece->points.clear();
        piece->color = c.uncovered[i] ? c.ink : kHiddenLineColor;
        for (std::size_t k = i; k <= last; ++k)
            piece->points.push_back(pointAlong(part.points, c.places[k]));
        if (piece->points.size() >= 2)
            out.push_back(std::move(piece));
        i = j + 1;
    }
    return out;
}

bool anyRunUncovered(const HiddenCandidate &c)
{
    return std::any_of(c.uncovered.begin(), c.uncovered.end(), [](char u) { return u != 0; });
}

} // namespace

std::vector<UncoveredPart> uncoveredParts(const StrokeGroup &before, const StrokeGroup &after,
                                          double closeGap)
{
    if (before.fills.empty() || (after.isDeformed() && after.rig.isPosed()) ||
        (before.isDeformed() && before.rig.isPosed()))
        return {};
    if (std::none_of(before.strokes.begin(), before.strokes.end(), isHiddenPart))
        return {};
    // The fills the edit took away: every line of theirs moved or gone. (An arm raised behind
    // the head and cut at its outline has the head's outline among its lines too: the arm's
    // fill did not go, and the body's line hidden under the arm stays hidden.)
    std::unordered_map<Id, const Stroke *> was;
    std::unordered_map<Id, const StrokeData *> now;
    for (const Stroke &s : before.strokes)
        was[s.id] = &s;
    for (const Stroke &s : after.strokes)
        now[s.id] = s.data.get();
    const auto edited = [&](const std::vector<Id> &ids) {
        return std::all_of(ids.begin(), ids.end(), [&](Id id) {
            const auto it = now.find(id);
            const auto at = was.find(id);
            return it == now.end() || at == was.end() || it->second != at->second->data.get();
        });
    };
    std::vector<char> gone(before.fills.size(), 0);
    for (std::size_t f = 0; f < before.fills.size(); ++f) {
        const Fill &fill = before.fills[f];
        const bool named = !fill.strokes.empty() || std::any_of(fill.more.begin(), fill.more.end(),
                                                                [](const FillPlace &place) {
                                                                    return !place.strokes.empty();
                                                                });
        gone[f] = named && edited(fill.strokes) &&
                  std::all_of(fill.more.begin(), fill.more.end(),
                              [&](const FillPlace &place) { return edited(place.strokes); });
    }
    if (std::none_of(gone.begin(), gone.end(), [](char g) { return g != 0; }))
        return {};
    const FillCover coverBefore(before, closeGap, gone);
    const FillCover coverAfter(after, closeGap);
    std::vector<UncoveredPart> out;
    std::vector<QRgb> inkOf;
    for (std::size_t i = 0; i < after.strokes.size(); ++i) {
        const Stroke &s = after.strokes[i];
        const auto it = was.find(s.id);
        if (!isHiddenPart(s) || it == was.end() || !isHiddenPart(*it->second) ||
            it->second->data->points.size() != s.data->points.size())
            continue;
        HiddenCandidate c;
        c.index = i;
        c.places = runSamples(s.data->points);
        if (c.places.empty())
            continue;
        const double width = double(s.data->width);
        c.uncovered.resize(c.places.size());
        for (std::size_t k = 0; k < c.places.size(); ++k) {
            // Covered before: under the fill on both sides. Uncovered after: no fill at the
            // line itself, so that a run inked ends on the edge of a fill still over the
            // line (the body's line at the neck, inked up to the arm's outline, not past it).
            const StrokePoint p = pointAlong(s.data->points, c.places[k]);
            c.uncovered[k] = coverBefore.covers(it->second->data->points, c.places[k], width) &&
                             !coverAfter.covers(QPointF(p.x, p.y));
        }
        smoothRuns(c.uncovered, s.data->points, c.places, width);
        if (!anyRunUncovered(c))
            continue;
        if (inkOf.empty()) { // the inked colour of each line of parts, once something is inked
            inkOf.assign(after.strokes.size(), 0xff000000);
            for (const std::vector<std::size_t> &line : linesOfParts(after)) {
                const auto inked = std::find_if(line.begin(), line.end(), [&](std::size_t k) {
                    return after.strokes[k].data && qAlpha(after.strokes[k].data->color) != 0;
                });
                for (std::size_t k : line)
                    inkOf[k] = inked != line.end() ? after.strokes[*inked].data->color : 0xff000000;
            }
        }
        c.ink = inkOf[i];
        out.push_back({s.id, piecesOfPart(*s.data, c)});
    }
    return out;
}
bool pushUncoveredParts(Document *doc, Id groupId, const StrokeGroup &before)
{
    const StrokeGroup *group = doc->group(groupId);
    if (!group)
        return false;
    const std::vector<UncoveredPart> parts =
        uncoveredParts(before, *group, doc->settings().closeGap);
    for (const UncoveredPart &p : parts) {
        if (p.pieces.size() == 1)
            doc->undoStack()->push(
                new ReplaceStrokeDataCommand(doc, {p.part}, p.pieces, Command::tr("Show Lines")));
        else
            pushStrokeCut(doc, p.part, p.pieces);
    }
    return !parts.empty();
}

} // namespace finbook::model
