#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/triangle_locator.h>
#include <finbook/model/erase/stroke_cut.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/inbetween/between_drawings.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QCoreApplication>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

namespace finbook::model {

namespace {

namespace between = deform::between;

// The sentences' translation context.
struct BetweenDrawings {
    Q_DECLARE_TR_FUNCTIONS(BetweenDrawings)
};

bool inked(const Stroke &s)
{
    return s.data && qAlpha(s.data->color) != 0 && !s.data->points.empty();
}

// The unit normal of a stroke at point k, from its neighbours two steps away; zero where the
// stroke has no direction there (a dot).
Eigen::Vector2d normalAt(const std::vector<StrokePoint> &points, std::size_t k)
{
    const std::size_t a = k >= 2 ? k - 2 : 0;
    const std::size_t b = std::min(points.size() - 1, k + 2);
    const Eigen::Vector2d d(points[b].x - points[a].x, points[b].y - points[a].y);
    const double length = d.norm();
    if (!(length > 1e-9))
        return Eigen::Vector2d::Zero();
    return Eigen::Vector2d(-d.y(), d.x()) / length;
}

// At most this many of A's stroke points pull on the fit (evenly along the strokes): beyond
// it, more samples cost time and add nothing the mesh can follow.
constexpr std::size_t kMaxSamples = 2000;
constexpr std::size_t kMaxTargetPoints = 6000;
// ... and none closer along its stroke than this (px) to the last one taken: a traced
// outline's points 0.8 px apart pulled no better than every other one, and each costs a
// nearest-point query per iteration. B's points, one per square of kTargetSpacing, are a little
// denser than A's samples, so that every sample finds one of B's within the spacing.
constexpr double kSampleSpacing = 2.0;
constexpr double kTargetSpacing = 1.5;
// A closed line of A (its ends within kClosedEnds px, or kClosedShare of its length) that
// overlaps a larger one — between kOverlapLow and kOverlapHigh of its points inside the larger
// one's outline, and some of the larger one's inside its own — is a part drawn over another
// (an arm's top over the body): it is meshed on its own and hinged to the other.
constexpr double kClosedEnds = 6.0;
constexpr double kClosedShare = 0.05;
constexpr double kOverlapLow = 0.02;
constexpr double kOverlapHigh = 0.6;
// A part longer than this many times its width is a limb: it turns about its end's middle.
constexpr double kLimbLength = 2.0;
// At most this many closed lines (the largest) are looked at as parts, each judged on at most
// kShareSamples of its points: a drawing of hundreds of closed scribbles costs no more.
constexpr std::size_t kMaxParts = 64;
constexpr std::size_t kShareSamples = 256;
// A line within kTouch px (and half the part's pen) of a part's outline touches it; one with
// kInsidePart of its points inside the outline, and none that near, lies in it.
constexpr double kTouch = 3.0;
constexpr double kInsidePart = 0.9;

// Affine coordinates of p in triangle (a, b, c), unclamped; nullopt for a triangle of no area.
std::optional<Eigen::RowVector3d> affineCoords(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                               const Eigen::Vector2d &b, const Eigen::Vector2d &c)
{
    const Eigen::Vector2d u = b - a, v = c - a, w = p - a;
    const double det = u.x() * v.y() - u.y() * v.x();
    const double scale = std::max(u.squaredNorm(), v.squaredNorm());
    if (!(std::abs(det) > 1e-9 * scale) || !std::isfinite(det))
        return std::nullopt;
    const double s = (w.x() * v.y() - w.y() * v.x()) / det;
    const double r = (u.x() * w.y() - u.y() * w.x()) / det;
    return Eigen::RowVector3d(1.0 - s - r, s, r);
}

Id largestId(const StrokeGroup &g)
{
    Id top = g.id;
    for (const Stroke &s : g.strokes)
        top = std::max(top, s.id);
    return top;
}

// The sentence for a fit that failed; empty for one that did not.
QString failure(const deform::between::RigidFitResult &r)
{
    namespace between = deform::between;
    if (r.status == between::FitStatus::Fitted)
        return {};
    const Eigen::AlignedBox2d &where = r.worstRegion;
    QString at;
    if (!where.isEmpty())
        at = BetweenDrawings::tr(
                 "The lines of the first key around (%1, %2), %3 × %4 px, find nothing "
                 "like them in the second key.")
                 .arg(qRound(where.center().x()))
                 .arg(qRound(where.center().y()))
                 .arg(qRound(where.sizes().x()))
                 .arg(qRound(where.sizes().y()));
    if (r.status == between::FitStatus::ResidualTooLarge && r.partUncovered) {
        const Eigen::AlignedBox2d &part = r.uncoveredRegion;
        return BetweenDrawings::tr(
                   "The first key's drawing cannot be laid on all of the second's: its lines "
                   "around (%1, %2), %3 × %4 px (%5 % of them), have nothing of the first key "
                   "on them. Draw a key between them, or draw the second closer to the first.")
            .arg(qRound(part.center().x()))
            .arg(qRound(part.center().y()))
            .arg(qRound(part.sizes().x()))
            .arg(qRound(part.sizes().y()))
            .arg(qRound(100.0 * r.uncoveredShare));
    }
    switch (r.status) {
    case between::FitStatus::ResidualTooLarge:
        return BetweenDrawings::tr(
                   "The two drawings are too different to fit one onto the other "
                   "(%1 % of the drawing apart on the median, %2 % stretched).%3 Draw a "
                   "key between them, or draw the second closer to the first.")
            .arg(100.0 * std::max(r.relativeMedian,
                                  r.targetDiagonal > 0 ? r.coverageMedian / r.targetDiagonal : 0.0),
                 0, 'f', 1)
            .arg(100.0 * r.distortion, 0, 'f', 0)
            .arg(at.isEmpty() ? QString() : QLatin1Char(' ') + at);
    case between::FitStatus::InvalidPins:
        return BetweenDrawings::tr("A correspondence pin is not on the first key's drawing.");
    case between::FitStatus::EmptyTarget:
        return BetweenDrawings::tr("The second key has no lines to fit to.");
    default:
        return BetweenDrawings::tr("The fit could not be solved.");
    }
}

// Points embedded in A's mesh posed as V (rows of meshed's V): with parts drawn over others,
// each in the topmost part whose triangles hold it (a click on an arm's top over the body means
// the arm), else in the rest's, else on the nearest triangle as geometry::embed puts it.
// Point location in each of A's meshes posed as V: each part's (topmost first), then the rest's;
// each with the row of F its triangles start at.
std::vector<std::pair<Eigen::Index, geometry::TriangleLocator>>
layerLocators(const DrawingFit &fit, const Eigen::MatrixX2d &V)
{
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    std::vector<std::pair<Eigen::Index, geometry::TriangleLocator>> layers;
    for (const LayeredPart &part : fit.parts)
        layers.emplace_back(
            part.firstTriangle,
            geometry::TriangleLocator(V, F.middleRows(part.firstTriangle, part.triangles)));
    layers.emplace_back(0, geometry::TriangleLocator(V, F.topRows(fit.restTriangles)));
    return layers;
}

geometry::Embedding embedOnTop(const DrawingFit &fit, const Eigen::MatrixX2d &V,
                               const Eigen::MatrixX2d &points)
{
    geometry::Embedding out = geometry::embed(V, fit.meshed->mesh.F, points);
    if (fit.parts.empty())
        return out;
    const auto layers = layerLocators(fit, V);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::Vector2d p = points.row(i).transpose();
        if (!p.allFinite())
            continue;
        for (const auto &[first, locator] : layers) {
            const geometry::Location at = locator.locate(p);
            if (at.inside && at.triangle >= 0) {
                out.I(i) = int(first) + at.triangle;
                out.B.row(i) = at.weights.transpose();
                break;
            }
        }
    }
    return out;
}

// The motion and B's points in the fitted mesh, once the fit is made. Empty, or what failed.
QString finish(DrawingFit &fitted)
{
    namespace between = deform::between;
    DrawingFit *const fit = &fitted;
    const between::RigidFitResult &r = fit->fit;
    const Eigen::MatrixX2d &V = fit->meshed->mesh.V;
    const Eigen::MatrixX3i &F = fit->meshed->mesh.F;
    const StrokeGroup &B = fit->b;
    const auto motion = between::arapInterpolationPrecompute(V, r.U, F, fit->hinges);
    if (!motion)
        return BetweenDrawings::tr("The fitted motion cannot be interpolated: %1")
            .arg(QString::fromStdString(motion.error().message));
    fit->motion = *motion;

    // B's points in the fitted mesh, to carry them backwards.
    std::vector<Eigen::Vector2d> bAll;
    for (const Stroke &s : B.strokes)
        if (s.data)
            for (const StrokePoint &p : s.data->points)
                bAll.emplace_back(p.x, p.y);
    Eigen::MatrixX2d BP(Eigen::Index(bAll.size()), 2);
    for (std::size_t i = 0; i < bAll.size(); ++i)
        BP.row(Eigen::Index(i)) = bAll[i].transpose();
    // embed snaps a point outside the mesh onto its nearest triangle; unclamped coordinates
    // in that triangle put it back exactly where B drew it.
    geometry::Embedding &inFit = fit->bInFit;
    inFit = embedOnTop(*fit, r.U, BP);
    for (Eigen::Index i = 0; i < BP.rows(); ++i) {
        const int t = inFit.I(i);
        if (t < 0)
            continue;
        const auto c = affineCoords(BP.row(i).transpose(), r.U.row(F(t, 0)).transpose(),
                                    r.U.row(F(t, 1)).transpose(), r.U.row(F(t, 2)).transpose());
        if (c)
            inFit.B.row(i) = *c;
    }

    return {};
}

// A fit made: refused with the reason, or finished (motion, B's embedding) and timed.
Expected<std::shared_ptr<const DrawingFit>, QString>
completed(std::shared_ptr<DrawingFit> fit, std::chrono::steady_clock::time_point started)
{
    if (const QString failed = failure(fit->fit); !failed.isEmpty())
        return finbook::unexpected(failed);
    if (const QString unfinished = finish(*fit); !unfinished.isEmpty())
        return finbook::unexpected(unfinished);
    fit->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return std::shared_ptr<const DrawingFit>(std::move(fit));
}

// A's parts drawn one over another: each such closed line meshed on its own, and the rest of
// A's lines meshed together as before; hinged where each part overlaps the one under it.
struct LayeredMesh {
    std::shared_ptr<const MeshedObject> meshed;
    std::vector<std::array<int, 2>> hinges;
    std::vector<LayeredPart> parts;
    Eigen::Index restTriangles = 0;
};

QRectF boundsOf(const std::vector<StrokePoint> &points)
{
    float left = points.front().x, right = left, top = points.front().y, bottom = top;
    for (const StrokePoint &p : points) {
        left = std::min(left, p.x);
        right = std::max(right, p.x);
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
    }
    return QRectF(QPointF(left, top), QPointF(right, bottom));
}

// A closed line as a region (geometry::regionContains: even-odd, so a line that crosses
// itself is still read as drawn), with its box and area, made once per line.
struct Outline {
    geometry::Region region;
    QRectF bounds;
    double area = 0.0;

    explicit Outline(const std::vector<StrokePoint> &points)
    {
        Eigen::MatrixX2d ring(Eigen::Index(points.size()), 2);
        for (std::size_t k = 0; k < points.size(); ++k)
            ring.row(Eigen::Index(k)) << points[k].x, points[k].y;
        area = std::abs(geometry::signedArea(ring));
        region = {geometry::Polygon{std::move(ring), {}}};
        bounds = points.empty() ? QRectF() : boundsOf(points);
    }
    bool contains(const Eigen::Vector2d &p) const
    {
        return bounds.contains(QPointF(p.x(), p.y())) &&
               geometry::regionContains(region, p.x(), p.y());
    }
};

bool closedLine(const Stroke &s)
{
    if (!inked(s) || s.data->points.size() < 8)
        return false;
    const std::vector<StrokePoint> &p = s.data->points;
    double length = 0.0;
    for (std::size_t k = 1; k < p.size(); ++k)
        length += std::hypot(p[k].x - p[k - 1].x, p[k].y - p[k - 1].y);
    const double ends = std::hypot(p.back().x - p.front().x, p.back().y - p.front().y);
    return ends <= std::max(kClosedEnds, kClosedShare * length);
}

// The share of `a`'s points inside `b`'s outline (judged on at most kShareSamples of them,
// evenly along a).
double shareInside(const std::vector<StrokePoint> &a, const Outline &b)
{
    if (a.empty() || !boundsOf(a).intersects(b.bounds))
        return 0.0;
    const std::size_t stride = std::max<std::size_t>(1, a.size() / kShareSamples);
    std::size_t in = 0, judged = 0;
    for (std::size_t k = 0; k < a.size(); k += stride, ++judged)
        in += b.contains(Eigen::Vector2d(a[k].x, a[k].y));
    return double(in) / double(judged);
}

// The share along segment a→b of the point nearest x (0 for a segment of no length).
double nearestShare(const Eigen::Vector2d &x, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d d = b - a;
    const double length = d.squaredNorm();
    return length > 0.0 ? std::clamp((x - a).dot(d) / length, 0.0, 1.0) : 0.0;
}

// The smallest distance from `line`'s points (at most kShareSamples of them) to the outline
// `ring` (its segments, closed).
double distanceTo(const std::vector<StrokePoint> &line, const std::vector<StrokePoint> &ring)
{
    const std::size_t stride = std::max<std::size_t>(1, line.size() / kShareSamples);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < line.size(); k += stride) {
        const Eigen::Vector2d x(line[k].x, line[k].y);
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
            const Eigen::Vector2d p(ring[j].x, ring[j].y), q(ring[i].x, ring[i].y);
            nearest = std::min(nearest, (x - (p + nearestShare(x, p, q) * (q - p))).norm());
        }
    }
    return nearest;
}

// Where a part drawn over another turns on it: for a limb (a part longer than kLimbLength
// times its width) the middle of its round end that lies over the other, half its width in
// from that end along its axis (an arm's top over the body: the shoulder); for a rounder part,
// the middle of where the two overlap (its points inside the other's outline and the other's
// inside its own). Nullopt when they do not overlap.
std::optional<Eigen::Vector2d> pivotOf(const std::vector<StrokePoint> &part,
                                       const Outline &partOutline,
                                       const std::vector<StrokePoint> &under,
                                       const Outline &underOutline)
{
    Eigen::Vector2d sum = Eigen::Vector2d::Zero(), centroid = Eigen::Vector2d::Zero();
    int count = 0;
    for (const StrokePoint &x : part) {
        centroid += Eigen::Vector2d(x.x, x.y);
        if (underOutline.contains(Eigen::Vector2d(x.x, x.y))) {
            sum += Eigen::Vector2d(x.x, x.y);
            ++count;
        }
    }
    for (const StrokePoint &x : under)
        if (partOutline.contains(Eigen::Vector2d(x.x, x.y))) {
            sum += Eigen::Vector2d(x.x, x.y);
            ++count;
        }
    if (count == 0 || part.empty())
        return std::nullopt;
    const Eigen::Vector2d overlap = sum / count;
    centroid /= double(part.size());
    Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
    for (const StrokePoint &x : part) {
        const Eigen::Vector2d d = Eigen::Vector2d(x.x, x.y) - centroid;
        covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> axes(covariance);
    const Eigen::Vector2d axis = axes.eigenvectors().col(1);
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const StrokePoint &x : part) {
        const double along = (Eigen::Vector2d(x.x, x.y) - centroid).dot(axis);
        low = std::min(low, along);
        high = std::max(high, along);
    }
    const double length = high - low;
    const double width = length > 0.0 ? partOutline.area / length : 0.0;
    if (!(length > kLimbLength * width))
        return overlap;
    // The end nearer the overlap lies over the other part.
    const double at = (overlap - centroid).dot(axis);
    const double end =
        std::abs(at - low) < std::abs(at - high) ? low + 0.5 * width : high - 0.5 * width;
    return Eigen::Vector2d(centroid + end * axis);
}

std::optional<LayeredMesh> layeredMesh(const StrokeGroup &a, double closeGap)
{
    // Closed lines, largest first; each that overlaps a larger one lies over it.
    std::vector<std::size_t> closed;
    std::map<std::size_t, Outline> outlines;
    for (std::size_t s = 0; s < a.strokes.size(); ++s) {
        if (!closedLine(a.strokes[s]))
            continue;
        Outline outline(a.strokes[s].data->points);
        if (outline.area > 100.0) {
            closed.push_back(s);
            outlines.emplace(s, std::move(outline));
        }
    }
    std::stable_sort(closed.begin(), closed.end(), [&](std::size_t x, std::size_t y) {
        return outlines.at(x).area > outlines.at(y).area;
    });
    closed.resize(std::min(closed.size(), kMaxParts));
    std::map<std::size_t, std::size_t> over; // part → the larger line it lies over
    for (std::size_t i = 1; i < closed.size(); ++i) {
        const auto &part = a.strokes[closed[i]].data->points;
        double most = 0.0;
        for (std::size_t j = 0; j < i; ++j) {
            const auto &under = a.strokes[closed[j]].data->points;
            const double share = shareInside(part, outlines.at(closed[j]));
            if (share >= kOverlapLow && share <= kOverlapHigh && share > most &&
                shareInside(under, outlines.at(closed[i])) > 0.0) {
                most = share;
                over[closed[i]] = closed[j];
            }
        }
    }
    // The other lines: one inside a part (a stripe on a sleeve) goes with it (with the smallest
    // part holding it); a part that another line touches or crosses (hair on a head, a hand
    // drawn at an arm's end, a line across the shoulder) is not a part on its own, since which
    // of the two that line goes with is not known. (Letting a line that touches a part and not
    // the line under it go with the part kept a bird's beak with its head, but a sheep's hair
    // tufts, bounded by the head's outline and each other, lost their fills.)
    std::map<std::size_t, std::size_t> inPart; // line → the part it lies in
    for (auto it = over.begin(); it != over.end();) {
        const auto &[part, under] = *it;
        const std::vector<StrokePoint> &outline = a.strokes[part].data->points;
        const double reach = kTouch + 0.5 * double(a.strokes[part].data->width);
        bool touched = false;
        std::vector<std::size_t> held;
        for (std::size_t s = 0; s < a.strokes.size() && !touched; ++s) {
            if (s == part || s == under || over.count(s) || !a.strokes[s].data ||
                a.strokes[s].data->points.size() < 2)
                continue;
            const std::vector<StrokePoint> &line = a.strokes[s].data->points;
            if (!inked(a.strokes[s])) {
                // A line of no ink (a gap closer) with both ends on the part closes the part's
                // own gap: it goes with it, or the gap opens as the part turns.
                const auto onPart = [&](const StrokePoint &end) {
                    return distanceTo({end}, outline) <= reach;
                };
                if (onPart(line.front()) && onPart(line.back()))
                    held.push_back(s);
                continue;
            }
            if (!boundsOf(line)
                     .adjusted(-reach, -reach, reach, reach)
                     .intersects(boundsOf(outline)))
                continue;
            const double inside = shareInside(line, outlines.at(part));
            const bool near = distanceTo(line, outline) <= reach;
            if (inside >= kInsidePart && !near)
                held.push_back(s);
            else
                touched = near || inside > 0.0;
        }
        if (touched) {
            it = over.erase(it);
            continue;
        }
        for (const std::size_t s : held) {
            const auto same = inPart.find(s);
            if (same == inPart.end() || outlines.at(part).area < outlines.at(same->second).area)
                inPart[s] = part;
        }
        ++it;
    }
    if (over.empty())
        return std::nullopt;
    // Meshes: the rest (every line not in a part over another), then each part with the lines
    // inside it. Each stroke's points go to its mesh's embedding.
    std::vector<std::vector<std::size_t>> meshStrokes(1);
    std::map<std::size_t, std::size_t> meshOf; // stroke → mesh
    for (const auto &[part, under] : over) {
        meshOf[part] = meshStrokes.size();
        meshStrokes.push_back({part});
    }
    for (std::size_t s = 0; s < a.strokes.size(); ++s) {
        if (over.count(s))
            continue;
        const auto held = inPart.find(s);
        const std::size_t k =
            held != inPart.end() && over.count(held->second) ? meshOf[held->second] : 0;
        meshOf[s] = k;
        meshStrokes[k].push_back(s);
    }
    // The rest first; each part then as finely as the rest (the vertices a mesh aims for are
    // the same whatever its size, so a part's density goes with the root of its share of the
    // rest's area), so the stack has about the vertices the whole would have.
    // Each meshed with the gap A's regions close (the automatic one follows the drawing's
    // size, and a body drawn open under an arm's top must still close without the arm).
    const double gap = objectRegions(a, closeGap)->regions().closeGap;
    std::vector<std::shared_ptr<const MeshedObject>> meshes;
    double restArea = 0.0;
    for (const std::vector<std::size_t> &strokes : meshStrokes) {
        MeshKey key = MeshKey::of(a, gap);
        key.strokes.clear();
        for (const std::size_t s : strokes)
            key.strokes.push_back(a.strokes[s].data);
        if (std::none_of(strokes.begin(), strokes.end(),
                         [&](std::size_t s) { return inked(a.strokes[s]); }))
            return std::nullopt;
        if (!meshes.empty() && restArea > 0.0)
            key.density =
                std::clamp(key.density * std::sqrt(outlines.at(strokes[0]).area / restArea), 0.05,
                           key.density);
        auto meshed = meshObject(key);
        if (!meshed)
            return std::nullopt;
        if (meshes.empty())
            restArea = geometry::triangleSignedAreas((*meshed)->mesh.V, (*meshed)->mesh.F)
                           .cwiseAbs()
                           .sum();
        meshes.push_back(*meshed);
    }
    // Stacked: vertices and triangles mesh after mesh; every A point (stroke after stroke)
    // embedded in its stroke's mesh.
    auto out = std::make_shared<MeshedObject>();
    std::vector<Eigen::Index> vertexOffset, triangleOffset;
    Eigen::Index n = 0, m = 0;
    for (const auto &mesh : meshes) {
        vertexOffset.push_back(n);
        triangleOffset.push_back(m);
        n += mesh->mesh.V.rows();
        m += mesh->mesh.F.rows();
    }
    out->mesh.region = meshes[0]->mesh.region;
    out->mesh.V.resize(n, 2);
    out->mesh.F.resize(m, 3);
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        out->mesh.V.middleRows(vertexOffset[k], meshes[k]->mesh.V.rows()) = meshes[k]->mesh.V;
        out->mesh.F.middleRows(triangleOffset[k], meshes[k]->mesh.F.rows()) =
            meshes[k]->mesh.F.array() + int(vertexOffset[k]);
    }
    std::size_t points = 0;
    out->strokeOffsets.push_back(0);
    for (const Stroke &s : a.strokes)
        out->strokeOffsets.push_back(points += s.data ? s.data->points.size() : 0);
    out->embedding.I = Eigen::VectorXi::Constant(Eigen::Index(points), -1);
    out->embedding.B = Eigen::MatrixX3d::Zero(Eigen::Index(points), 3);
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        for (std::size_t i = 0; i < meshStrokes[k].size(); ++i) {
            const std::size_t s = meshStrokes[k][i];
            const std::size_t from = meshes[k]->strokeOffsets[i], to = out->strokeOffsets[s];
            const std::size_t count = meshes[k]->strokeOffsets[i + 1] - from;
            for (std::size_t r = 0; r < count; ++r) {
                const int t = meshes[k]->embedding.I(Eigen::Index(from + r));
                out->embedding.I(Eigen::Index(to + r)) = t < 0 ? -1 : t + int(triangleOffset[k]);
                out->embedding.B.row(Eigen::Index(to + r)) =
                    meshes[k]->embedding.B.row(Eigen::Index(from + r));
            }
        }
    }
    // Each part's hinge: where it turns on the line under it (pivotOf), the vertex of the
    // part's mesh nearest it and the vertex of the under line's mesh nearest that.
    LayeredMesh layered;
    for (const auto &[part, under] : over) {
        const std::optional<Eigen::Vector2d> pivot =
            pivotOf(a.strokes[part].data->points, outlines.at(part), a.strokes[under].data->points,
                    outlines.at(under));
        if (!pivot)
            continue;
        const Eigen::RowVector2d centre = pivot->transpose();
        const auto nearestIn = [&](std::size_t k, const Eigen::RowVector2d &at) {
            Eigen::Index best = 0;
            (meshes[k]->mesh.V.rowwise() - at).rowwise().squaredNorm().minCoeff(&best);
            return int(vertexOffset[k] + best);
        };
        const int mine = nearestIn(meshOf[part], centre);
        const int theirs = nearestIn(meshOf[under], out->mesh.V.row(mine));
        layered.hinges.push_back({theirs, mine});
    }
    layered.restTriangles = meshes[0]->mesh.F.rows();
    for (const auto &[part, under] : over) {
        const std::size_t k = meshOf[part];
        layered.parts.push_back(
            LayeredPart{part, triangleOffset[k], meshes[k]->mesh.F.rows(), std::nullopt});
    }
    std::sort(layered.parts.begin(), layered.parts.end(),
              [](const LayeredPart &x, const LayeredPart &y) { return x.stroke > y.stroke; });
    layered.meshed = std::move(out);
    return layered;
}

// The point of stroke s of g nearest p.
LineAnchor anchorOn(const StrokeGroup &g, std::size_t s, const Eigen::Vector2d &p)
{
    LineAnchor best{s, {}};
    const std::vector<StrokePoint> &points = g.strokes[s].data->points;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const Eigen::Vector2d a(points[k].x, points[k].y), b(points[k + 1].x, points[k + 1].y);
        const double t = nearestShare(p, a, b);
        const double distance = (p - (a + t * (b - a))).norm();
        if (distance < nearest) {
            nearest = distance;
            best.place = geometry::PolylinePlace{Eigen::Index(k), t};
        }
    }
    return best;
}

// What each of A's parts drawn over others shows (DrawingFit::parts), and what A shows under
// them (DrawingFit::underFills): A's fills over A's faces with the parts' lines left out, so
// that the body is its own colour where an arm's top covered it.
void layerFills(DrawingFit &fit)
{
    const StrokeGroup &a = fit.a;
    if (a.fills.empty() || fit.parts.empty())
        return;
    const ObjectRegionsPtr shown = objectRegions(a, fit.closeGap);
    const std::vector<int> shownFills = faceFills(*shown, a.fills);
    fit.shownRegions = shown;
    fit.shownFills.assign(shownFills.size(), std::nullopt);
    for (std::size_t f = 0; f < shownFills.size(); ++f)
        if (shownFills[f] >= 0)
            fit.shownFills[f] = a.fills[std::size_t(shownFills[f])];
    const auto fillAt = [&](const Eigen::Vector2d &p) -> std::optional<Fill> {
        const int face = shown->faceAt(QPointF(p.x(), p.y()));
        if (face < 0 || shownFills[std::size_t(face)] < 0)
            return std::nullopt;
        return a.fills[std::size_t(shownFills[std::size_t(face)])];
    };
    // A part shows the fill most of its triangles show (those under no part drawn after it).
    std::map<std::size_t, Outline> outlines; // each part's, at rest
    for (const LayeredPart &part : fit.parts)
        outlines.emplace(part.stroke, Outline(a.strokes[part.stroke].data->points));
    const Eigen::MatrixX2d &V = fit.meshed->mesh.V;
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    for (LayeredPart &part : fit.parts) {
        std::map<std::size_t, int> votes;
        for (Eigen::Index t = part.firstTriangle; t < part.firstTriangle + part.triangles; ++t) {
            const Eigen::Vector2d c =
                (V.row(F(t, 0)) + V.row(F(t, 1)) + V.row(F(t, 2))).transpose() / 3.0;
            // Under a part drawn after it, it does not show.
            if (std::any_of(fit.parts.begin(), fit.parts.end(), [&](const LayeredPart &other) {
                    return other.stroke > part.stroke && outlines.at(other.stroke).contains(c);
                }))
                continue;
            const int face = shown->faceAt(QPointF(c.x(), c.y()));
            if (face >= 0)
                ++votes[std::size_t(shownFills[std::size_t(face)] + 1)];
        }
        const auto most =
            std::max_element(votes.begin(), votes.end(),
                             [](const auto &x, const auto &y) { return x.second < y.second; });
        if (most != votes.end() && most->first > 0)
            part.fill = a.fills[most->first - 1];
    }
    // Under the parts: A without their lines.
    StrokeGroup under = a;
    under.strokes.clear();
    std::vector<std::size_t> underIndex; // under's strokes → A's
    for (std::size_t s = 0; s < a.strokes.size(); ++s)
        if (std::none_of(fit.parts.begin(), fit.parts.end(),
                         [s](const LayeredPart &p) { return p.stroke == s; })) {
            under.strokes.push_back(a.strokes[s]);
            underIndex.push_back(s);
        }
    // The gap A's regions closed (the automatic one follows the drawing's size, which the
    // parts' lines are part of).
    fit.underRegions = objectRegions(under, shown->regions().closeGap);
    // The gaps A's lines under the parts close once the parts' lines are left out (a body's
    // outline drawn with a gap an arm's top covered): each end on its line, to be closed in
    // every in-between by a line of no ink, or the body's region opens into the part's as the
    // part turns away.
    for (const geometry::GapClosure &c : fit.underRegions->regions().closures) {
        const int from = fit.underRegions->strokeOfInput(c.fromStroke);
        const int to = fit.underRegions->strokeOfInput(c.toStroke);
        if (from < 0 || to < 0 || std::size_t(from) >= underIndex.size() ||
            std::size_t(to) >= underIndex.size())
            continue;
        const std::size_t sf = underIndex[std::size_t(from)], st = underIndex[std::size_t(to)];
        fit.underClosures.push_back({anchorOn(a, sf, c.from), anchorOn(a, st, c.to)});
    }
    fit.underFills.assign(std::size_t(fit.underRegions->faceCount()), std::nullopt);
    // Each under face shows the fill of A's face its seed lies in, unless that is a part's
    // (the face under an arm's top): then the fill of A's largest face within it that no part
    // covers.
    const auto partAt = [&](const Eigen::Vector2d &p) {
        return std::any_of(outlines.begin(), outlines.end(),
                           [&](const auto &outline) { return outline.second.contains(p); });
    };
    const geometry::Regions &shownFaces = shown->regions();
    for (int face = 0; face < fit.underRegions->faceCount(); ++face) {
        const geometry::Face &f = fit.underRegions->regions().faces[std::size_t(face)];
        double largest = 0.0;
        for (std::size_t g = 0; g < shownFaces.faces.size(); ++g) {
            const geometry::Face &inA = shownFaces.faces[g];
            if (shownFills[g] < 0 || partAt(inA.seed) || !(inA.area > largest) ||
                fit.underRegions->faceAt(QPointF(inA.seed.x(), inA.seed.y())) != face)
                continue;
            largest = inA.area;
            fit.underFills[std::size_t(face)] = a.fills[std::size_t(shownFills[g])];
        }
        if (largest == 0.0)
            fit.underFills[std::size_t(face)] = fillAt(f.seed);
    }
}

// Correspondence pins as the fit takes them: each A point in A's mesh.
deform::between::FitPins fitPinsOf(const std::vector<BetweenPin> &pins, const DrawingFit &fit)
{
    deform::between::FitPins fitPins;
    if (pins.empty())
        return fitPins;
    Eigen::MatrixX2d onA(Eigen::Index(pins.size()), 2);
    fitPins.targets.resize(Eigen::Index(pins.size()), 2);
    for (std::size_t i = 0; i < pins.size(); ++i) {
        onA.row(Eigen::Index(i)) << pins[i].onA.x(), pins[i].onA.y();
        fitPins.targets.row(Eigen::Index(i)) << pins[i].onB.x(), pins[i].onB.y();
    }
    fitPins.where = embedOnTop(fit, fit.meshed->mesh.V, onA);
    return fitPins;
}

} // namespace

StrokeGroup shownDrawing(const StrokeGroup &group, double closeGap,
                         const std::function<Id()> &newId)
{
    StrokeGroup out = group;
    out.rig = Rig();
    out.deformed = nullptr;
    out.swap = SwapLink();
    if (!group.isDeformed() || group.deformed->strokes.size() != group.strokes.size())
        return out;
    AppliedPose applied = applyPoseToDrawing(group, closeGap, newId);
    out.strokes = std::move(applied.strokes);
    out.fills = std::move(applied.fills);
    return out;
}

Expected<std::shared_ptr<const DrawingFit>, QString>
fitDrawings(const StrokeGroup &a, const StrokeGroup &b, double closeGap,
            const std::vector<BetweenPin> &pins, const BetweenOptions &options)
{
    const auto started = std::chrono::steady_clock::now();
    auto fit = std::make_shared<DrawingFit>();
    Id next = std::max(largestId(a), largestId(b));
    const auto newId = [&next] { return ++next; };
    fit->a = shownDrawing(a, closeGap, newId);
    fit->b = shownDrawing(b, closeGap, newId);
    fit->closeGap = closeGap;
    const StrokeGroup &A = fit->a;
    const StrokeGroup &B = fit->b;
    if (std::none_of(A.strokes.begin(), A.strokes.end(), inked))
        return finbook::unexpected(BetweenDrawings::tr("The first key has no lines to carry."));
    if (std::none_of(B.strokes.begin(), B.strokes.end(), inked))
        return finbook::unexpected(BetweenDrawings::tr("The second key has no lines to fit to."));

    // A's automatic skeleton (the articulated start) is built while A is meshed: neither needs
    // the other, and each takes tens of milliseconds on a large drawing.
    std::future<Expected<SkeletonRig, QString>> skeletonBuilt;
    if (options.articulated)
        skeletonBuilt = std::async(std::launch::async, [&A, closeGap] {
            return buildSkeletonRig(A, {}, std::nullopt, closeGap);
        });
    if (options.layeredParts)
        if (auto layered = layeredMesh(A, closeGap)) {
            fit->meshed = std::move(layered->meshed);
            fit->hinges = std::move(layered->hinges);
            fit->parts = std::move(layered->parts);
            fit->restTriangles = layered->restTriangles;
            layerFills(*fit);
        }
    if (!fit->meshed) {
        const auto meshed = meshObject(MeshKey::of(A, closeGap));
        if (!meshed)
            return finbook::unexpected(
                BetweenDrawings::tr("The first key could not be meshed: %1").arg(meshed.error()));
        fit->meshed = *meshed;
    }
    const Eigen::MatrixX2d &V = fit->meshed->mesh.V;
    const Eigen::MatrixX3i &F = fit->meshed->mesh.F;
    const geometry::Embedding &all = fit->meshed->embedding;

    // A's samples: its inked stroke points that lie in the mesh and have a direction.
    std::size_t inkedPoints = 0;
    for (const Stroke &s : A.strokes)
        inkedPoints += inked(s) ? s.data->points.size() : 0;
    const std::size_t stride =
        std::max<std::size_t>(1, (inkedPoints + kMaxSamples - 1) / kMaxSamples);
    std::vector<Eigen::Index> rows;
    std::vector<Eigen::Vector2d> normals;
    std::size_t counted = 0;
    for (std::size_t s = 0; s < A.strokes.size(); ++s) {
        if (!inked(A.strokes[s]))
            continue;
        const std::vector<StrokePoint> &points = A.strokes[s].data->points;
        double since = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < points.size(); ++k, ++counted) {
            if (k > 0)
                since += std::hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y);
            if (counted % stride != 0 || since < kSampleSpacing)
                continue;
            const Eigen::Index row = Eigen::Index(fit->meshed->strokeOffsets[s] + k);
            const Eigen::Vector2d n = normalAt(points, k);
            if (row >= all.I.size() || all.I(row) < 0 || n.isZero())
                continue;
            since = 0.0;
            rows.push_back(row);
            normals.push_back(n);
        }
    }
    if (rows.empty())
        return finbook::unexpected(
            BetweenDrawings::tr("The first key's lines are dots: there is nothing to fit."));
    geometry::Embedding samples;
    samples.I.resize(Eigen::Index(rows.size()));
    samples.B.resize(Eigen::Index(rows.size()), 3);
    Eigen::MatrixX2d N(Eigen::Index(rows.size()), 2);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        samples.I(Eigen::Index(i)) = all.I(rows[i]);
        samples.B.row(Eigen::Index(i)) = all.B.row(rows[i]);
        N.row(Eigen::Index(i)) = normals[i].transpose();
    }
    const auto source = between::rigidFitPrecompute(V, F, samples, N, fit->hinges);
    if (!source)
        return finbook::unexpected(BetweenDrawings::tr("The first key's mesh cannot be fitted: %1")
                                       .arg(QString::fromStdString(source.error().message)));
    fit->source = *source;

    // B's points: every inked stroke point with its normal, thinned to one in each
    // kTargetSpacing square — the one nearest its middle — and taken square by square (at most
    // kMaxTargetPoints, evenly), so that neither the order nor the direction B's lines were
    // drawn in changes them.
    struct Kept {
        Eigen::Vector2d point, normal;
        double off = 0.0;
        auto order() const { return std::tuple(off, point.x(), point.y(), normal.x(), normal.y()); }
    };
    std::map<std::pair<std::int64_t, std::int64_t>, Kept> squares;
    for (const Stroke &s : B.strokes) {
        if (!inked(s))
            continue;
        const std::vector<StrokePoint> &points = s.data->points;
        for (std::size_t k = 0; k < points.size(); ++k) {
            Eigen::Vector2d n = normalAt(points, k);
            if (n.isZero())
                continue;
            if (n.x() < 0.0 || (n.x() == 0.0 && n.y() < 0.0)) // either way along the line
                n = -n;
            const Eigen::Vector2d p(points[k].x, points[k].y);
            const double sx = std::floor(p.x() / kTargetSpacing),
                         sy = std::floor(p.y() / kTargetSpacing);
            const Kept kept{
                p, n, (p - kTargetSpacing * Eigen::Vector2d(sx + 0.5, sy + 0.5)).squaredNorm()};
            const auto [at, fresh] =
                squares.try_emplace({std::int64_t(sy), std::int64_t(sx)}, kept);
            if (!fresh && kept.order() < at->second.order())
                at->second = kept;
        }
    }
    const std::size_t bStride =
        std::max<std::size_t>(1, (squares.size() + kMaxTargetPoints - 1) / kMaxTargetPoints);
    Eigen::MatrixX2d P(Eigen::Index((squares.size() + bStride - 1) / bStride), 2), NB(P.rows(), 2);
    Eigen::Index taken = 0;
    counted = 0;
    for (const auto &[square, kept] : squares) {
        if (counted++ % bStride != 0)
            continue;
        P.row(taken) = kept.point.transpose();
        NB.row(taken++) = kept.normal.transpose();
    }
    fit->target = between::rigidFitTarget(P, NB);

    const between::FitPins fitPins = fitPinsOf(pins, *fit);
    between::FitSkeleton &skeleton = fit->skeleton;
    if (skeletonBuilt.valid())
        if (const auto built = skeletonBuilt.get()) {
            for (const QPointF &j : built->joints)
                skeleton.joints.emplace_back(j.x(), j.y());
            skeleton.parent = built->parent;
        }
    fit->fit = between::rigidFit(*fit->source, *fit->target, fitPins, skeleton, options.fit);
    fit->pins = pins;
    return completed(std::move(fit), started);
}

Expected<std::shared_ptr<const DrawingFit>, QString>
refitDrawings(const DrawingFit &previous, const std::vector<BetweenPin> &pins,
              const BetweenOptions &options)
{
    const auto started = std::chrono::steady_clock::now();
    auto fit = std::make_shared<DrawingFit>(previous);
    fit->pins = pins;
    fit->fit = deform::between::rigidRefit(*fit->source, *fit->target, fitPinsOf(pins, *fit),
                                           previous.fit, options.fit);
    return completed(std::move(fit), started);
}

KeyFits fitKeyDrawings(const Frame &first, const Frame &second, double closeGap,
                       const BetweenOptions &options)
{
    KeyFits out;
    for (const int i : differentDrawings(first, second)) {
        const auto fit = fitDrawings(first.groups[std::size_t(i)], second.groups[std::size_t(i)],
                                     closeGap, {}, options);
        if (!fit) {
            out.failures.emplace_back(i, fit.error());
            continue;
        }
        out.fits.resize(std::max(out.fits.size(), std::size_t(i) + 1));
        out.fits[std::size_t(i)] = *fit;
    }
    return out;
}

namespace {

// The fitted motion at t, n×2.
Eigen::MatrixX2d motionAt(const DrawingFit &fit, double t)
{
    if (const auto solved = between::arapInterpolate(*fit.motion, t); solved && solved->allFinite())
        return *solved;
    return (1.0 - t) * fit.meshed->mesh.V + t * fit.fit.U; // never seen; finite at least
}

double clampedTime(double t)
{
    return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
}

// How far into the cross-fade t is: 0 before it, 1 at the second key.
double fadeAt(double t, const BetweenOptions &options)
{
    const double fade =
        std::clamp(std::isfinite(options.crossFade) ? options.crossFade : 0.0, 0.0, 1.0);
    return fade > 0.0 && t > 1.0 - fade ? (t - (1.0 - fade)) / fade : 0.0;
}

// `rest` posed by the carried points (rest's strokes moved, same order).
StrokeGroup posedBy(const StrokeGroup &rest, const StrokeGroup &carried)
{
    StrokeGroup posed = rest;
    auto points = std::make_shared<DeformedStrokes>();
    for (const Stroke &stroke : carried.strokes)
        points->strokes.push_back(stroke.data ? stroke.data->points : std::vector<StrokePoint>{});
    posed.deformed = std::move(points);
    posed.rig.pins = {Pin{kNoId, QPointF(), QPointF()}}; // posed: shown as deformed
    return posed;
}

// `carried` (rest's strokes moved, same order and ids) with Apply Pose's lines and fills:
// `rest` posed by the carried points, its pose applied. Ids of the lines it adds follow the
// largest of either.
StrokeGroup appliedAsShown(const StrokeGroup &rest, StrokeGroup carried, double closeGap)
{
    const StrokeGroup posed = posedBy(rest, carried);
    Id next = std::max(largestId(rest), largestId(carried));
    AppliedPose applied = applyPoseToDrawing(posed, closeGap, [&next] { return ++next; });
    // Apply Pose's strokes are the posed points; the carried ones hold the faded ink.
    for (Stroke &stroke : applied.strokes) {
        const auto same = std::find_if(carried.strokes.begin(), carried.strokes.end(),
                                       [&](const Stroke &c) { return c.id == stroke.id; });
        if (same != carried.strokes.end() && same->data && stroke.data &&
            same->data->points == stroke.data->points)
            stroke.data = same->data;
    }
    carried.strokes = std::move(applied.strokes);
    carried.fills = std::move(applied.fills);
    return carried;
}

QRgb faded(QRgb colour, double keep)
{
    if (qAlpha(colour) == 0)
        return colour; // a line of no ink stays one
    const int alpha = std::max(1, int(std::lround(qAlpha(colour) * keep)));
    return qRgba(qRed(colour), qGreen(colour), qBlue(colour), alpha);
}

// Moves the points of `group`'s strokes, stroke after stroke, to the rows of `points` (as
// many as the strokes have points) and keeps `keep` of their ink's alpha.
void carryStrokes(StrokeGroup &group, const Eigen::MatrixX2d &points, double keep)
{
    Eigen::Index row = 0;
    for (Stroke &stroke : group.strokes) {
        if (!stroke.data)
            continue;
        auto data = std::make_shared<StrokeData>(*stroke.data);
        for (StrokePoint &p : data->points) {
            if (row < points.rows()) {
                p.x = float(points(row, 0));
                p.y = float(points(row, 1));
            }
            ++row;
        }
        data->color = faded(data->color, keep);
        stroke.data = std::move(data);
    }
}

// Where a point the carried mesh U holds (`at`, in triangles from row `first` of F) lies at
// rest (F's rows of V).
Eigen::Vector2d atRest(const geometry::Location &at, Eigen::Index first, const Eigen::MatrixX2d &V,
                       const Eigen::MatrixX3i &F)
{
    const Eigen::Index t = first + at.triangle;
    return (at.weights(0) * V.row(F(t, 0)) + at.weights(1) * V.row(F(t, 1)) +
            at.weights(2) * V.row(F(t, 2)))
        .transpose();
}

// The fills of an in-between of a fit with parts drawn over others (DrawingFit::parts): the
// carried lines' faces, each showing what A shows where the topmost part's carried mesh that
// holds its seed takes it back to, else what A shows under the parts where the rest's carried
// mesh does, else none (the space an arm swung out of, between it and the body).
std::vector<Fill> layeredFills(const DrawingFit &fit, const StrokeGroup &carried,
                               const Eigen::MatrixX2d &Ut)
{
    std::vector<Fill> out;
    const ObjectRegionsPtr regions = objectRegions(carried, fit.closeGap);
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    const Eigen::MatrixX2d &V = fit.meshed->mesh.V;
    const auto layers = layerLocators(fit, Ut); // the parts' as carried, then the rest's
    const geometry::TriangleLocator &rest = layers.back().second;
    for (int face = 0; face < regions->faceCount(); ++face) {
        const Eigen::Vector2d seed = regions->regions().faces[std::size_t(face)].seed;
        std::optional<Fill> shows;
        bool onPart = false;
        // On the topmost part whose carried mesh holds it (its outline, and the lines that
        // went with it: a beak on a head), what A shows where that mesh takes it back to (a
        // stripe on a sleeve keeps its colour).
        for (std::size_t k = 0; k < fit.parts.size() && !onPart; ++k) {
            const LayeredPart &part = fit.parts[k];
            const geometry::Location at = layers[k].second.locate(seed);
            if (!at.inside || at.triangle < 0)
                continue;
            onPart = true;
            const Eigen::Vector2d back = atRest(at, part.firstTriangle, V, F);
            const int inA = fit.shownRegions->faceAt(QPointF(back.x(), back.y()));
            shows = inA >= 0 ? fit.shownFills[std::size_t(inA)] : part.fill;
        }
        if (!onPart && fit.underRegions) {
            const geometry::Location at = rest.locate(seed);
            if (at.inside && at.triangle >= 0) {
                const Eigen::Vector2d back = atRest(at, 0, V, F);
                const int under = fit.underRegions->faceAt(QPointF(back.x(), back.y()));
                if (under >= 0)
                    shows = fit.underFills[std::size_t(under)];
            }
        }
        if (!shows)
            continue;
        Fill fill = fillOfFace(*regions, face, shows->color);
        fill.shading = shows->shading;
        out.push_back(std::move(fill));
    }
    return out;
}

} // namespace

StrokeGroup betweenDrawing(const DrawingFit &fit, double t, const BetweenOptions &options)
{
    t = clampedTime(t);
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    const Eigen::MatrixX2d Ut = motionAt(fit, t);
    const double w = fadeAt(t, options);
    StrokeGroup out = fit.a;
    carryStrokes(out, geometry::applyEmbedding(fit.meshed->embedding, Ut, F), 1.0 - w);
    if (!fit.parts.empty() && !out.fills.empty()) {
        // A gap A's regions closed stays closed (a part's open end against the line under it
        // may leave the Close gaps distance as the part turns), as Apply Pose keeps it.
        Id next = std::max(largestId(fit.a), largestId(out));
        for (Stroke &closer : keptGapClosers(posedBy(fit.a, out), out.strokes, fit.closeGap,
                                             [&next] { return ++next; }))
            out.strokes.push_back(std::move(closer));
        const double width = medianInkWidth(fit.a.strokes);
        const auto carriedTo = [&out](const LineAnchor &at) {
            const StrokePoint p = pointAlong(out.strokes[at.stroke].data->points, at.place);
            return QPointF(p.x, p.y);
        };
        for (const auto &[from, to] : fit.underClosures)
            out.strokes.push_back(
                Stroke{++next, lineOfNoInk({carriedTo(from), carriedTo(to)}, width)});
        out.fills = layeredFills(fit, out, Ut);
        return out;
    }
    // The drawing as Apply Pose makes a pose of it (rig_commands.h applyPoseToDrawing): A
    // posed by the carried points shows its rest regions carried whole; the carried lines get
    // lines of no ink where a gap the pose showed closed opened on the way or colours it showed
    // apart joined, and each fill the faces that showed its colour (a leg passing another keeps
    // its colour).
    if (!out.fills.empty())
        out = appliedAsShown(fit.a, std::move(out), fit.closeGap);
    return out;
}

std::optional<StrokeGroup> fadingInDrawing(const DrawingFit &fit, double t,
                                           const BetweenOptions &options)
{
    t = clampedTime(t);
    const double w = fadeAt(t, options);
    if (!(w > 0.0))
        return std::nullopt;
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    const Eigen::MatrixX2d Ut = motionAt(fit, t);
    StrokeGroup out = fit.b;
    carryStrokes(out, geometry::applyEmbedding(fit.bInFit, Ut, F), w);
    if (!out.fills.empty()) { // as A's (betweenDrawing): B posed backwards, its pose applied
        out = appliedAsShown(fit.b, std::move(out), fit.closeGap);
        for (Fill &f : out.fills)
            f.color = faded(f.color, w);
    }
    return out;
}

} // namespace finbook::model
