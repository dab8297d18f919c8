// finbook-bench limbs [options] FILE...: every limb of the automatic skeleton
// (a branch ending in a tip, tests/bench/limb_measures.h) turned at its base joint by +60°,
// −60°, +100° and −100° in each skinning scheme, on the mesh the app builds (about 1,500
// vertices). Per limb, scheme and angle one JSON line: outline self-crossings near the joint
// (folds: both edges within 3 joint radii of the pivot at rest) and elsewhere (overlaps: the
// limb passing over the body), flipped triangles, the area within 1.5 joint radii of the pivot (%
// of rest), how far the rest of the body moved (max over vertices outside that disk whose nearest
// bone is not the limb's, % of the shape's diagonal) and the solve time; then one summary line per
// scheme and angle over all limbs of all files (clean: no fold and no flip; clean or passing
// over: no flip, and any fold is where the limb cut off and turned rigidly, as a cut-out puppet,
// would cross the body's outline near the joint too: passes_over). Schemes: rigid and lbs
// (plain bone boundary conditions), rigid_zones and lbs_zones (joint zones of
// deform::kDefaultJointFree radii left to the solve; rigid_zones is the app's Rigid mode), and
// candidates that lost (skin_alternatives.h): rigid_pieces (whatever one bone dominates moves
// exactly with it, only blended flesh is left to ARAP), cutout (every vertex follows its
// dominant bone alone: a cut-out puppet on the uncut mesh), rigid_zones_drag (the app's pins
// solved by the Refined method's Drag stage, with its flip repair, instead of the paper's two
// steps) and skeleton-driven ARAP (bench::skeletonArapHolds: everything outside the joint
// zones moves rigidly with its bone, the zones are solved) with the Drag stage
// (skeleton_arap), the two steps (skeleton_arap_two_step) and the converged Final stage
// (skeleton_arap_final); and cutout_layers, the app's Cut-out mode (deform::cutAtJoints: the
// mesh cut where limbs narrow or hang from a junction, each piece skinned by its own bones):
// its outline crossings count as folds only within one piece (and not between edges from two
// copies of one vertex, which touch in every pose), those of two pieces are one drawn over the
// other (layered); base_cut says whether the limb's base joint was cut. joint_cover_pct: the
// area of the joint disk the drawing's outline and the cuts' round joints cover (non-zero
// rule, lines across a cut running straight from piece to piece, as the app draws them), % of
// rest.
// Per file and scheme one line with the skinning precompute's time (weights, cut, ARAP
// factorization) and, cut, how many joints were cut.
// --before: the skeleton without the animator rig (RefineOptions::animatorRig off).
// --as-strokes: silhouettes' contours as the app imports them (closed 3 px strokes, placed as
// `finbook-bench import` places them, through the object's shape). --only A,B:
// just these schemes. Sweeps: --joint-free X (the zones' factor), --dominance X (rigid_pieces),
// --reach X (SkinningOptions::reach), --child-zone X, --parent-zone X, --arap-dominance X,
// --thinnest 0|1, --soft-limbs 0|1 (bench::SkeletonArapOptions).
// --png DIR: one contact sheet of every ±60° pose per file, DIR/poses_*.png (flipped
// triangles red, pivots as red dots), of the scheme --scheme NAME (default rigid_zones);
// --png-degrees 100: the ±100° poses instead (DIR/poses100_*.png); --zoom: each cell shows 8
// joint radii around the pivot, with the ARAP pins as green dots.
#include "../deform/skin_test_support.h"
#include "bench.h"
#include "limb_measures.h"
#include "skin_alternatives.h"

#include <finbook/deform/skeleton/cut_out.h>
#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace {

using namespace finbook;
using bench::Limb;
using Clock = std::chrono::steady_clock;

constexpr double kDegrees[] = {60.0, -60.0, 100.0, -100.0};
constexpr double kJointDisk = 1.5; // joint radii around the pivot
constexpr int kCell = 320;         // px per pose on the contact sheet
constexpr double kFoldDisk = 3.0;  // joint radii: outline crossings nearer than this are folds
// Joint radii: a limb cut off and turned rigidly that crosses the body this near the pivot
// passes over it (passesOver).
constexpr double kPassDisk = 6.0;
constexpr double kZoomRadii = 8.0; // --zoom: joint radii from the pivot to a cell's edge

struct Scheme {
    const char *name;
    bool rigid;
    double jointFree;
    double dominance = 2.0;    // ≤ 1: rigid pieces (bench::rigidPieces)
    bool hardCut = false;      // linear blend with one-hot weights (bench::hardCut)
    bool skeletonArap = false; // pins from deform::skeletonArapHolds
    int stage = -1;      // rigid schemes: −1 arapSolve's two steps, else ArapStage (Drag, Final)
    bool cutOut = false; // the mesh cut at its joints (deform::cutAtJoints), pieces layered
};
constexpr Scheme kSchemes[] = {
    {"rigid", true, 0.0},
    {"lbs", false, 0.0},
    {"rigid_zones", true, deform::kDefaultJointFree},
    {"lbs_zones", false, deform::kDefaultJointFree},
    {"rigid_pieces", true, deform::kDefaultJointFree, 0.9},
    {"cutout", false, 0.0, 2.0, true},
    {"rigid_zones_drag", true, deform::kDefaultJointFree, 2.0, false, false,
     int(deform::ArapStage::Drag)},
    {"skeleton_arap", true, 0.0, 2.0, false, true, int(deform::ArapStage::Drag)},
    {"skeleton_arap_two_step", true, 0.0, 2.0, false, true, -1},
    {"skeleton_arap_final", true, 0.0, 2.0, false, true, int(deform::ArapStage::Final)},
    {"cutout_layers", true, deform::kDefaultJointFree, 2.0, false, false, -1, true}};

constexpr const char *kUsage =
    "[--before] [--as-strokes] [--only A,B] [--png DIR] [--png-degrees 60|100] [--zoom] [--scheme "
    "NAME] "
    "[--joint-free X] [--dominance X] [--reach X] [--child-zone X] [--parent-zone X] "
    "[--arap-dominance X] [--thinnest 0|1] [--soft-limbs 0|1] FILE... (every limb turned "
    "±60°/±100° at its base)";

struct Sample {
    int folds = 0, crossings = 0, flips = 0;
    int layered = 0; // cutout_layers: crossings of two pieces' outlines (one drawn over the other)
    double jointArea = 100.0, jointCover = 100.0, bodyMoved = 0.0, ms = 0.0;
};

struct Skinned {
    std::shared_ptr<const deform::SkinningWeights> weights;
    deform::SkinBinding vertices;
    std::shared_ptr<const deform::RigidSkinning> rigid;
    std::optional<deform::CutMesh> cut; // cutout_layers: the mesh it skins
};

// --joint-free, --dominance and --reach: the zone factor of the *_zones and rigid_pieces
// schemes, rigid_pieces' dominance and SkinningOptions::reach of every scheme, for sweeps
// (negative: the schemes' own).
struct Tuning {
    double jointFree = -1.0, dominance = -1.0, reach = -1.0;
    bench::SkeletonArapOptions arap;
};
Tuning tuning;

std::optional<Skinned> skinFor(const geometry::ObjectMesh &mesh, const deform::Skeleton &skeleton,
                               const geometry::Skeleton &s, const Scheme &scheme)
{
    // The rigid scheme with zones is the app's: plain weights, zones in the pins only
    // (deform::withJointZones); lbs_zones puts them in the weights' boundary.
    deform::SkinningOptions options;
    options.jointRadius = s.radius;
    if (tuning.reach >= 0.0)
        options.reach = tuning.reach;
    const double free =
        tuning.jointFree >= 0.0 && scheme.jointFree > 0.0 ? tuning.jointFree : scheme.jointFree;
    options.jointFree = scheme.rigid ? 0.0 : free;
    const double dominance =
        tuning.dominance >= 0.0 && scheme.dominance <= 1.0 ? tuning.dominance : scheme.dominance;
    auto weights = deform::computeSkinningWeights(mesh.V, mesh.F, skeleton, options);
    if (!weights)
        return std::nullopt;
    if (scheme.cutOut) {
        // The app's Cut-out mode: the mesh cut at its joints, each piece skinned by its own
        // bones with the Rigid mode's joint zones where it was not cut.
        auto cut = deform::cutAtJoints(mesh.V, mesh.F, skeleton, s.radius);
        if (!cut)
            return std::nullopt;
        const deform::SkinningWeights pieces = deform::cutOutWeights(**weights, skeleton, *cut);
        auto rigid = deform::rigidSkinPrecompute(
            cut->V, cut->F, deform::withJointZones(pieces, cut->V, skeleton, s.radius, free));
        if (!rigid)
            return std::nullopt;
        return Skinned{*weights, deform::bindVertices(pieces, cut->V), *rigid, std::move(*cut)};
    }
    Skinned out{
        *weights,
        deform::bindVertices(scheme.hardCut ? bench::hardCut(**weights) : **weights, mesh.V),
        nullptr, std::nullopt};
    if (scheme.rigid) {
        const deform::SkinningWeights pins =
            scheme.skeletonArap
                ? bench::skeletonArapHolds(**weights, mesh.V, skeleton, s.radius, tuning.arap)
            : scheme.dominance <= 1.0
                ? bench::rigidPieces(**weights, mesh.V, skeleton, s.radius, free, dominance)
                : deform::withJointZones(**weights, mesh.V, skeleton, s.radius, free);
        auto rigid = deform::rigidSkinPrecompute(mesh.V, mesh.F, pins);
        if (!rigid)
            return std::nullopt;
        out.rigid = *rigid;
    }
    return out;
}

// The mesh a scheme moves: the object's, or its cut (cutout_layers), whose pieces are drawn
// one over the other.
struct Moved {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    Eigen::VectorXi piece;                        // per vertex (−1 everywhere uncut)
    std::vector<std::pair<int, int>> outline;     // boundary edges of every piece
    std::vector<int> edgePiece;                   // the piece of each
    std::vector<std::pair<int, int>> drawing;     // bench::drawingOutline
    Eigen::VectorXi source;                       // vertex → the uncut mesh's vertex it copies
    Eigen::MatrixX2d socketPoints;                // the sockets' rest points
    std::vector<std::pair<int, int>> socketEdges; // into [V; socketPoints]
};

Moved movedMesh(const geometry::ObjectMesh &mesh, const deform::Skeleton &skeleton,
                const Skinned &skinned)
{
    Moved m;
    m.V = skinned.cut ? skinned.cut->V : mesh.V;
    m.F = skinned.cut ? skinned.cut->F : mesh.F;
    m.piece = Eigen::VectorXi::Constant(m.V.rows(), -1);
    std::map<std::pair<int, int>, int> pieceOf;
    for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
        const int piece = skinned.cut ? skinned.cut->piece(t) : -1;
        for (int k = 0; k < 3; ++k) {
            const int a = m.F(t, k), b = m.F(t, (k + 1) % 3);
            pieceOf[{std::min(a, b), std::max(a, b)}] = piece;
            m.piece(a) = piece;
        }
    }
    m.outline = bench::boundaryEdges(m.F);
    for (const auto &e : m.outline)
        m.edgePiece.push_back(pieceOf[e]);
    m.drawing = bench::drawingOutline(mesh.F, m.F);
    // The sockets the app paints under turned limbs, in the fill: each cut's round end
    // (JointCut::round), a disk at its joint touching the outline, which a limb's turn leaves
    // where it is. Their points follow the mesh's in the arrays coveredArea is given.
    if (skinned.cut) {
        std::vector<Eigen::RowVector2d> points;
        const auto addLoop = [&](const std::vector<Eigen::RowVector2d> &loop) {
            const int first = int(m.V.rows() + Eigen::Index(points.size()));
            for (std::size_t i = 0; i < loop.size(); ++i) {
                points.push_back(loop[i]);
                m.socketEdges.emplace_back(first + int(i), first + int((i + 1) % loop.size()));
            }
        };
        // Loops turning as the triangles do, so the non-zero rule adds them up.
        const double sense = bench::signedTriangleArea(m.V, m.F, 0) < 0.0 ? -1.0 : 1.0;
        for (std::size_t c = 0; c < skinned.cut->cuts.size(); ++c) {
            const deform::JointCut &at = skinned.cut->cuts[c];
            if (at.round > 0.0 && at.joint >= 0 && at.joint < skeleton.jointCount()) {
                std::vector<Eigen::RowVector2d> disk;
                for (int i = 0; i < 64; ++i) {
                    const double angle = sense * 2.0 * M_PI * i / 64.0;
                    disk.push_back(skeleton.joints.row(at.joint) +
                                   at.round * Eigen::RowVector2d(std::cos(angle), std::sin(angle)));
                }
                addLoop(disk);
            }
        }
        m.socketPoints.resize(Eigen::Index(points.size()), 2);
        for (std::size_t i = 0; i < points.size(); ++i)
            m.socketPoints.row(Eigen::Index(i)) = points[i];
    }
    m.source =
        skinned.cut
            ? skinned.cut->source
            : Eigen::VectorXi(Eigen::VectorXi::LinSpaced(m.V.rows(), 0, int(m.V.rows()) - 1));
    return m;
}

// Vertices that belong to neither the limb nor the joint disk: their nearest bone is not one
// of the limb's (nor, cut, is their piece one of the limb's pieces).
// onLimb gets, for every vertex, whether its nearest bone is one of the limb's.
std::vector<int> bodyVertices(const Moved &mesh, const geometry::Skeleton &s, const Limb &limb,
                              const std::vector<int> &limbPieces, std::vector<char> &onLimb)
{
    onLimb.assign(std::size_t(mesh.V.rows()), 0);
    std::vector<char> inLimb(std::size_t(s.jointCount()), 0);
    for (int j : limb.joints)
        inLimb[std::size_t(j)] = 1;
    const Eigen::Vector2d pivot = s.joints.row(limb.base).transpose();
    const double disk = kJointDisk * s.radius(limb.base);
    std::vector<int> body;
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
        const Eigen::Vector2d p = mesh.V.row(v).transpose();
        double best = INFINITY;
        int owner = -1;
        for (int j = 0; j < s.jointCount(); ++j) {
            if (s.parent(j) < 0)
                continue;
            const Eigen::Vector2d a = s.joints.row(s.parent(j)).transpose();
            const Eigen::Vector2d b = s.joints.row(j).transpose();
            const Eigen::Vector2d ab = b - a;
            const double t = ab.squaredNorm() > 0
                                 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                                 : 0.0;
            const double d = (p - a - t * ab).norm();
            if (d < best) {
                best = d;
                owner = j;
            }
        }
        onLimb[std::size_t(v)] = owner >= 0 && inLimb[std::size_t(owner)];
        const bool limbPiece =
            std::find(limbPieces.begin(), limbPieces.end(), mesh.piece(v)) != limbPieces.end();
        if (!onLimb[std::size_t(v)] && !limbPiece && (p - pivot).norm() > disk)
            body.push_back(int(v));
    }
    return body;
}

// Whether the limb, cut off and turned rigidly by T over an unmoved body (a cut-out puppet's
// pose), crosses the body's outline near the joint: then a crossing there is the limb passing
// over the body, which no skinning can avoid, rather than a fold. Only crossings of an outline
// edge of the limb with one of the body count (edges across the cut are stretched there).
bool passesOver(const geometry::ObjectMesh &mesh, const std::vector<std::pair<int, int>> &outline,
                const std::vector<char> &onLimb, const deform::BoneTransform &T,
                const Eigen::Vector2d &pivot, double foldRadius)
{
    Eigen::MatrixX2d R = mesh.V;
    for (Eigen::Index v = 0; v < R.rows(); ++v) {
        if (onLimb[std::size_t(v)])
            R.row(v) = deform::transformPoint(T, mesh.V.row(v).transpose()).transpose();
    }
    const auto side = [&](int edge) {
        const auto &[a, b] = outline[std::size_t(edge)];
        return onLimb[std::size_t(a)] == onLimb[std::size_t(b)] ? int(onLimb[std::size_t(a)]) : -1;
    };
    const auto near = [&](int edge) {
        return (mesh.V.row(outline[std::size_t(edge)].first).transpose() - pivot).norm() <=
               foldRadius;
    };
    for (const auto &[e, f] : bench::outlineCrossings(R, outline)) {
        if (side(e) >= 0 && side(f) >= 0 && side(e) != side(f) && near(e) && near(f))
            return true;
    }
    return false;
}

Sample measurePose(const Moved &mesh, const Eigen::MatrixX2d &U, const Eigen::Vector2d &pivot,
                   double disk, const std::vector<int> &body, double diagonal)
{
    Sample out;
    // A crossing of two outline edges that both start near the joint is a fold there; any
    // other is the limb passing over the body (or another limb), which a turn may well do.
    // Edges of two pieces of a cut mesh cross where one piece is drawn over the other.
    const auto &outline = mesh.outline;
    for (const auto &[e, f] : bench::outlineCrossings(U, outline)) {
        // Edges from two copies of one vertex (a piece's outline pinched where two cuts leave
        // one joint) meet there in every pose, as edges sharing a vertex do: not a fold.
        const auto &[e0, e1] = outline[std::size_t(e)];
        const auto &[f0, f1] = outline[std::size_t(f)];
        if (mesh.source(e0) == mesh.source(f0) || mesh.source(e0) == mesh.source(f1) ||
            mesh.source(e1) == mesh.source(f0) || mesh.source(e1) == mesh.source(f1))
            continue;
        const auto near = [&](int edge) {
            return (mesh.V.row(outline[std::size_t(edge)].first).transpose() - pivot).norm() <=
                   kFoldDisk / kJointDisk * disk;
        };
        if (mesh.edgePiece[std::size_t(e)] != mesh.edgePiece[std::size_t(f)])
            ++out.layered;
        else
            ++(near(e) && near(f) ? out.folds : out.crossings);
    }
    std::vector<std::pair<int, int>> drawing = mesh.drawing;
    drawing.insert(drawing.end(), mesh.socketEdges.begin(), mesh.socketEdges.end());
    const auto withSockets = [&](const Eigen::MatrixX2d &P) {
        Eigen::MatrixX2d all(P.rows() + mesh.socketPoints.rows(), 2);
        all << P, mesh.socketPoints;
        return all;
    };
    const double restCover = bench::coveredArea(withSockets(mesh.V), drawing, pivot, disk);
    out.jointCover =
        restCover > 0.0
            ? 100.0 * bench::coveredArea(withSockets(U), drawing, pivot, disk) / restCover
            : 100.0;
    double rest = 0.0, posed = 0.0;
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
        const double r = bench::signedTriangleArea(mesh.V, mesh.F, t);
        const double p = bench::signedTriangleArea(U, mesh.F, t);
        out.flips += r * p <= 0.0 ? 1 : 0;
        const Eigen::Vector2d c =
            (mesh.V.row(mesh.F(t, 0)) + mesh.V.row(mesh.F(t, 1)) + mesh.V.row(mesh.F(t, 2)))
                .transpose() /
            3.0;
        if ((c - pivot).norm() <= disk) {
            rest += r;
            posed += p;
        }
    }
    out.jointArea = rest > 0.0 ? 100.0 * posed / rest : 100.0;
    for (int v : body)
        out.bodyMoved = std::max(out.bodyMoved, (U.row(v) - mesh.V.row(v)).norm());
    out.bodyMoved *= 100.0 / diagonal;
    return out;
}

struct Summary {
    std::vector<double> folds, crossings, flips, jointArea, jointCover, bodyMoved, ms;
    int layered = 0;     // poses where one piece of a cut mesh crosses over another
    int clean = 0;       // poses with no fold and no flip
    int cleanOrOver = 0; // no flip, and no fold or the limb passes over the body (passesOver)
};

// A cut mesh is drawn piece after piece (parents first), each opaque over the ones before
// with its own outline, as the pieces of a cut-out puppet lie.
void drawPose(QPainter &painter, const Moved &mesh, const Eigen::MatrixX2d &U,
              const Eigen::Vector2d &pivot, const QRectF &cell, const Eigen::RowVector2d &lo,
              double scale, const Eigen::VectorXi &pins)
{
    painter.save();
    painter.setClipRect(cell);
    painter.translate(cell.topLeft());
    painter.scale(scale, scale);
    painter.translate(-lo.x(), -lo.y());
    const int last = mesh.piece.size() ? mesh.piece.maxCoeff() : -1;
    for (int piece = -1; piece <= last; ++piece) {
        for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
            if (mesh.piece(mesh.F(t, 0)) != piece)
                continue;
            const bool flipped = bench::signedTriangleArea(mesh.V, mesh.F, t) *
                                     bench::signedTriangleArea(U, mesh.F, t) <=
                                 0.0;
            QPolygonF tri;
            for (int k = 0; k < 3; ++k)
                tri << QPointF(U(mesh.F(t, k), 0), U(mesh.F(t, k), 1));
            painter.setPen(
                QPen(flipped ? QColor(255, 40, 40) : QColor(190, 206, 235), 0.5 / scale));
            painter.setBrush(flipped ? QColor(255, 40, 40) : QColor(190, 206, 235));
            painter.drawPolygon(tri);
        }
        painter.setPen(QPen(Qt::black, 1.0 / scale));
        for (std::size_t e = 0; e < mesh.outline.size(); ++e) {
            if (mesh.edgePiece[e] != piece)
                continue;
            const auto &[a, b] = mesh.outline[e];
            painter.drawLine(QPointF(U(a, 0), U(a, 1)), QPointF(U(b, 0), U(b, 1)));
        }
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 120, 0));
    for (const int v : pins)
        painter.drawEllipse(QPointF(U(v, 0), U(v, 1)), 1.2 / scale, 1.2 / scale);
    painter.setBrush(Qt::red);
    painter.drawEllipse(QPointF(pivot.x(), pivot.y()), 3.0 / scale, 3.0 / scale);
    painter.restore();
}

int benchLimbs(const QStringList &arguments)
{
    QStringList args = arguments;
    bool before = false, asStrokes = false;
    QString pngDir;
    int pngScheme = 2;
    bool zoom = false;
    int pngDegrees = 60;
    QStringList only; // --only A,B: just these schemes
    double thinnest = tuning.arap.thinnest ? 1.0 : 0.0, softLimbs = tuning.arap.softLimbs;
    double degrees = pngDegrees;
    const std::map<QString, double *> knobs = {
        {QStringLiteral("--joint-free"), &tuning.jointFree},
        {QStringLiteral("--dominance"), &tuning.dominance},
        {QStringLiteral("--reach"), &tuning.reach},
        {QStringLiteral("--child-zone"), &tuning.arap.childZone},
        {QStringLiteral("--parent-zone"), &tuning.arap.parentZone},
        {QStringLiteral("--arap-dominance"), &tuning.arap.dominance},
        {QStringLiteral("--thinnest"), &thinnest},
        {QStringLiteral("--soft-limbs"), &softLimbs},
        {QStringLiteral("--png-degrees"), &degrees}};
    while (!args.isEmpty() && args.front().startsWith(QStringLiteral("--"))) {
        if (args.front() == QStringLiteral("--before")) {
            before = true;
            args.removeFirst();
        } else if (args.front() == QStringLiteral("--as-strokes")) {
            asStrokes = true;
            args.removeFirst();
        } else if (args.front() == QStringLiteral("--only") && args.size() >= 2) {
            only = args[1].split(QLatin1Char(','));
            args = args.mid(2);
        } else if (args.front() == QStringLiteral("--zoom")) {
            zoom = true;
            args.removeFirst();
        } else if (args.front() == QStringLiteral("--scheme") && args.size() >= 2) {
            for (int k = 0; k < int(std::size(kSchemes)); ++k)
                pngScheme = args[1] == QLatin1String(kSchemes[k].name) ? k : pngScheme;
            args = args.mid(2);
        } else if (args.size() >= 2 && knobs.count(args.front())) {
            *knobs.at(args.front()) = args[1].toDouble();
            args = args.mid(2);
        } else if (args.front() == QStringLiteral("--png") && args.size() >= 2) {
            pngDir = args[1];
            args = args.mid(2);
            QDir().mkpath(pngDir);
        } else {
            break;
        }
    }
    // --only without the drawn scheme among them draws the first of them (blank sheets before).
    if (!only.isEmpty() && !only.contains(QLatin1String(kSchemes[pngScheme].name)))
        for (int k = int(std::size(kSchemes)) - 1; k >= 0; --k)
            pngScheme = only.contains(QLatin1String(kSchemes[k].name)) ? k : pngScheme;
    tuning.arap.thinnest = thinnest != 0.0;
    tuning.arap.softLimbs = softLimbs != 0.0;
    pngDegrees = degrees >= 80.0 ? 100 : 60;
    if (args.isEmpty()) {
        std::fprintf(stderr, "usage: finbook-bench limbs %s\n", kUsage);
        return 2;
    }
    std::map<std::pair<int, int>, Summary> summary; // (scheme, angle index)
    int limbCount = 0, failures = 0;
    for (const QString &path : args) {
        const QString name = QFileInfo(path).baseName();
        const auto mesh = test::meshDataFile(path, {}, asStrokes);
        geometry::RefineOptions refine;
        refine.animatorRig = !before;
        std::optional<geometry::Skeleton> s;
        std::optional<deform::Skeleton> skeleton;
        if (mesh) {
            auto built = geometry::skeletonize(mesh->region, {}, refine);
            if (built && built->jointCount() > 0)
                s = std::move(*built);
        }
        if (s) {
            auto made = deform::makeSkeleton(s->joints, s->parent);
            if (made)
                skeleton = std::move(*made);
        }
        if (!skeleton) {
            ++failures;
            std::printf("{\"file\":\"%s\",\"error\":\"no mesh or skeleton\"}\n", qPrintable(name));
            continue;
        }
        const Eigen::RowVector2d lo = mesh->V.colwise().minCoeff(),
                                 hi = mesh->V.colwise().maxCoeff();
        const double diagonal = (hi - lo).norm();
        const auto outline = bench::boundaryEdges(mesh->F);
        const std::vector<Limb> limbs = bench::findLimbs(*s);
        limbCount += int(limbs.size());
        const double scale = (kCell - 10) / std::max(1.0, (hi - lo).maxCoeff() * 1.6);
        QImage sheet(std::max<int>(1, int(limbs.size())) * kCell, 2 * kCell, QImage::Format_RGB32);
        sheet.fill(Qt::white);
        QPainter painter(&sheet);
        painter.setRenderHint(QPainter::Antialiasing);
        for (int k = 0; k < int(std::size(kSchemes)); ++k) {
            const Scheme &scheme = kSchemes[k];
            if (!only.isEmpty() && !only.contains(QLatin1String(scheme.name)))
                continue;
            const auto built = Clock::now();
            const auto skinned = skinFor(*mesh, *skeleton, *s, scheme);
            if (!skinned) {
                ++failures;
                continue;
            }
            std::printf("{\"file\":\"%s\",\"scheme\":\"%s\",\"vertices\":%d,\"cuts\":%d,"
                        "\"precompute_ms\":%.2f}\n",
                        qPrintable(name), scheme.name, int(mesh->V.rows()),
                        skinned->cut ? int(skinned->cut->cuts.size()) : 0,
                        std::chrono::duration<double, std::milli>(Clock::now() - built).count());
            const Moved moved = movedMesh(*mesh, *skeleton, *skinned);
            const Eigen::VectorXi bonePiece =
                skinned->cut ? deform::bonePieces(*skeleton, *skinned->cut)
                             : Eigen::VectorXi::Constant(skeleton->jointCount(), -1);
            for (std::size_t l = 0; l < limbs.size(); ++l) {
                const Limb &limb = limbs[l];
                std::vector<char> onLimb;
                std::vector<int> limbPieces;
                for (const int j : limb.joints)
                    if (bonePiece(j) >= 0 && bonePiece(j) != bonePiece(limb.base))
                        limbPieces.push_back(bonePiece(j));
                const std::vector<int> body = bodyVertices(moved, *s, limb, limbPieces, onLimb);
                const Eigen::Vector2d pivot = s->joints.row(limb.base).transpose();
                for (int a = 0; a < int(std::size(kDegrees)); ++a) {
                    deform::SkeletonPose pose = deform::restPose(*skeleton);
                    pose.angles(limb.first) = kDegrees[a] * M_PI / 180.0;
                    const auto start = Clock::now();
                    const auto posed = deform::forwardKinematics(*skeleton, pose);
                    Eigen::MatrixX2d U = moved.V;
                    if (scheme.rigid && scheme.stage >= 0) {
                        Eigen::MatrixX2d targets;
                        deform::skin(skinned->rigid->pins, *posed, targets);
                        (void)deform::arapSolve(*skinned->rigid->arap, targets, U,
                                                deform::ArapStage(scheme.stage));
                    } else if (scheme.rigid)
                        (void)deform::rigidSkinSolve(*skinned->rigid, *posed, U);
                    else
                        deform::skin(skinned->vertices, *posed, U);
                    const double ms =
                        std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                    Sample m = measurePose(moved, U, pivot, kJointDisk * s->radius(limb.base), body,
                                           diagonal);
                    m.ms = ms;
                    const bool over =
                        m.folds > 0 && passesOver(*mesh, outline, onLimb,
                                                  posed->transforms[std::size_t(limb.first)], pivot,
                                                  kPassDisk * s->radius(limb.base));
                    Summary &sum = summary[{k, a}];
                    sum.cleanOrOver += m.flips == 0 && (m.folds == 0 || over) ? 1 : 0;
                    sum.folds.push_back(m.folds);
                    sum.crossings.push_back(m.crossings);
                    sum.flips.push_back(m.flips);
                    sum.jointArea.push_back(m.jointArea);
                    sum.jointCover.push_back(m.jointCover);
                    sum.layered += m.layered > 0 ? 1 : 0;
                    sum.bodyMoved.push_back(m.bodyMoved);
                    sum.ms.push_back(ms);
                    sum.clean += m.folds == 0 && m.flips == 0 ? 1 : 0;
                    std::printf("{\"file\":\"%s\",\"limb\":%d,\"tip\":%d,\"base\":%d,"
                                "\"scheme\":\"%s\",\"degrees\":%g,\"folds\":%d,\"overlaps\":%d,"
                                "\"flips\":%d,\"passes_over\":%d,\"layered\":%d,\"base_cut\":%d,"
                                "\"joint_area_pct\":%.1f,\"joint_cover_pct\":%.1f,"
                                "\"body_moved_pct\":%.2f,\"ms\":%.2f}\n",
                                qPrintable(name), int(l), limb.tip, limb.base, scheme.name,
                                kDegrees[a], m.folds, m.crossings, m.flips, int(over), m.layered,
                                int(bonePiece(limb.first) != bonePiece(limb.base)), m.jointArea,
                                m.jointCover, m.bodyMoved, ms);
                    if (!pngDir.isEmpty() && k == pngScheme &&
                        std::abs(kDegrees[a]) == double(pngDegrees)) {
                        // --zoom: 16 joint radii around the pivot per cell, pins drawn.
                        const double r = kZoomRadii * s->radius(limb.base);
                        drawPose(painter, moved, U, pivot,
                                 QRectF(double(l) * kCell + 5, (a % 2) * kCell + 5, kCell - 10,
                                        kCell - 10),
                                 zoom ? Eigen::RowVector2d(pivot.transpose().array() - r)
                                      : Eigen::RowVector2d(lo - 0.3 * (hi - lo)),
                                 zoom ? (kCell - 10) / (2.0 * r) : scale,
                                 zoom && skinned->rigid ? skinned->rigid->pinVertices
                                                        : Eigen::VectorXi());
                    }
                }
            }
        }
        painter.end();
        if (!pngDir.isEmpty() && !limbs.empty())
            sheet.save(QDir(pngDir).filePath(
                QStringLiteral("poses%1_%2.png")
                    .arg(pngDegrees == 60 ? QString() : QString::number(pngDegrees), name)));
        std::fflush(stdout);
    }
    using bench::median;
    using bench::percentile;
    for (const auto &[key, sum] : summary) {
        const int n = int(sum.flips.size());
        std::printf(
            "{\"summary\":true,\"scheme\":\"%s\",\"degrees\":%g,\"limbs\":%d,"
            "\"clean_pct\":%.1f,\"clean_or_passing_over_pct\":%.1f,\"no_overlap_pct\":%.1f,"
            "\"median_flips\":%g,"
            "\"median_folds\":%g,\"median_overlaps\":%g,"
            "\"joint_area_pct_p5\":%.1f,\"joint_area_pct_median\":%.1f,"
            "\"joint_area_pct_p95\":%.1f,\"joint_cover_pct_p5\":%.1f,"
            "\"joint_cover_pct_median\":%.1f,\"joint_cover_pct_p95\":%.1f,"
            "\"joint_cover_90_110_pct\":%.1f,\"layered_pct\":%.1f,\"body_moved_pct_median\":%.2f,"
            "\"body_moved_pct_p95\":%.2f,\"body_moved_le1_pct\":%.1f,\"median_ms\":%.2f}\n",
            kSchemes[key.first].name, kDegrees[key.second], n, n ? 100.0 * sum.clean / n : 0.0,
            n ? 100.0 * sum.cleanOrOver / n : 0.0,
            n ? 100.0 * double(std::count(sum.crossings.begin(), sum.crossings.end(), 0.0)) / n
              : 0.0,
            median(sum.flips), median(sum.folds), median(sum.crossings),
            percentile(sum.jointArea, 0.05), median(sum.jointArea), percentile(sum.jointArea, 0.95),
            percentile(sum.jointCover, 0.05), median(sum.jointCover),
            percentile(sum.jointCover, 0.95),
            n ? 100.0 *
                    double(std::count_if(sum.jointCover.begin(), sum.jointCover.end(),
                                         [](double c) { return c >= 90.0 && c <= 110.0; })) /
                    n
              : 0.0,
            n ? 100.0 * sum.layered / n : 0.0, median(sum.bodyMoved),
            percentile(sum.bodyMoved, 0.95),
            n ? 100.0 *
                    double(std::count_if(sum.bodyMoved.begin(), sum.bodyMoved.end(),
                                         [](double d) { return d <= 1.0; })) /
                    n
              : 0.0,
            median(sum.ms));
    }
    std::printf("{\"summary\":true,\"files\":%d,\"limbs\":%d,\"failures\":%d}\n", int(args.size()),
                limbCount, failures);
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("limbs", kUsage, benchLimbs);
