#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/model/inbetween/between_drawings.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QCoreApplication>

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

// The motion and B's points in the fitted mesh, once the fit is made. Empty, or what failed.
QString finish(DrawingFit &fitted)
{
    namespace between = deform::between;
    DrawingFit *const fit = &fitted;
    const between::RigidFitResult &r = fit->fit;
    const Eigen::MatrixX2d &V = fit->meshed->mesh.V;
    const Eigen::MatrixX3i &F = fit->meshed->mesh.F;
    const StrokeGroup &B = fit->b;
    const auto motion = between::arapInterpolationPrecompute(V, r.U, F);
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
    inFit = geometry::embed(r.U, F, BP);
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

// Correspondence pins as the fit takes them: each A point in A's mesh.
deform::between::FitPins fitPinsOf(const std::vector<BetweenPin> &pins, const Eigen::MatrixX2d &V,
                                   const Eigen::MatrixX3i &F)
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
    fitPins.where = geometry::embed(V, F, onA);
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
    const auto meshed = meshObject(MeshKey::of(A, closeGap));
    if (!meshed)
        return finbook::unexpected(
            BetweenDrawings::tr("The first key could not be meshed: %1").arg(meshed.error()));
    fit->meshed = *meshed;
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
    const auto source = between::rigidFitPrecompute(V, F, samples, N);
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

    const between::FitPins fitPins = fitPinsOf(pins, V, F);
    between::FitSkeleton &skeleton = fit->skeleton;
    if (skeletonBuilt.valid())
        if (const auto built = skeletonBuilt.get()) {
            for (const QPointF &j : built->joints)
                skeleton.joints.emplace_back(j.x(), j.y());
            skeleton.parent = built->parent;
        }
    fit->fit = between::rigidFit(*fit->source, *fit->target, fitPins, skeleton, options.fit);
    fit->closeGap = closeGap;
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
    fit->fit = deform::between::rigidRefit(
        *fit->source, *fit->target, fitPinsOf(pins, fit->meshed->mesh.V, fit->meshed->mesh.F),
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

// `carried` (rest's strokes moved, same order and ids) with Apply Pose's lines and fills:
// `rest` posed by the carried points, its pose applied. Ids of the lines it adds follow the
// largest of either.
StrokeGroup appliedAsShown(const StrokeGroup &rest, StrokeGroup carried, double closeGap)
{
    StrokeGroup posed = rest;
    auto points = std::make_shared<DeformedStrokes>();
    for (const Stroke &stroke : carried.strokes)
        points->strokes.push_back(stroke.data ? stroke.data->points : std::vector<StrokePoint>{});
    posed.deformed = std::move(points);
    posed.rig.pins = {Pin{kNoId, QPointF(), QPointF()}}; // posed: shown as deformed
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

} // namespace

StrokeGroup betweenDrawing(const DrawingFit &fit, double t, const BetweenOptions &options)
{
    t = clampedTime(t);
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    const Eigen::MatrixX2d Ut = motionAt(fit, t);
    const double w = fadeAt(t, options);
    StrokeGroup out = fit.a;
    carryStrokes(out, geometry::applyEmbedding(fit.meshed->embedding, Ut, F), 1.0 - w);
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
