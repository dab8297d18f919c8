// finbook-bench looks [--png DIR] [--degrees A,B,...] FILE...: Cut-out turns judged from the
// picture, as an animator judges them (issue 48). For each real drawing (filled as
// finbook-bench bake fills it, each fill its own colour), its automatic skeleton in the Cut-out
// skinning, and each limb (a bone leaving a limb base, as finbook-bench bake turns them) turned
// alone by each angle (default ±60° and ±100°), the posed object is drawn as the app draws it
// (paintFrame: fills under lines, the pieces' layers, sockets and all) and compared with the
// paper cut-out of the app's own cut: each piece (the roots' first, then each cut's over the
// ones before) showing the rest picture moved by the piece's motion. A piece that did not move
// rigidly (a limb not cut at its base: cut false) is judged as a paper limb cut where the bones
// meet (pixels nearest a bone of the turned limb turned with it, the others left in place).
// The sockets (a cut's round end in the limb's fill) may be filled. Each turn is looked at in a
// 480 px square around its pivot that holds the limb in every turn, magnified up to 1.5×. Per
// turn, in its pixels (tolerance: the pen's width there, at least 2 px):
//   spill_px:  fill pixels outside every piece and socket (socket fill sticking out past the
//              outline, a fill pulled out of shape);
//   wedge_px:  pixels the paper pieces show filled that the picture leaves white (a white wedge
//              between limb and body, a torn fill);
//   stray_px:  ink far from the outlines as the paper pieces show them (the body's hidden
//              under the limb), off a socket's round edge: stubs, hooks, crossed line ends,
//              doubled arcs, a chord across the joint, a line showing through the limb;
//   broken_px: outline the paper pieces show, away from the sockets, that the picture does not
//              draw (a broken or missing outline);
//   free_ends: line ends within 3 joint disks of the pivot that the turn made: ends of the
//              painted runs (paintLayers), not a stroke's own end, that the picture shows as an
//              end (ink there, crossing a circle two pens round it once: stubs and hooks at a
//              cut, where a line that goes on, or runs on hidden under a fill, does not count).
// Marks in pieces under 3 px (or a pen's width) are specks of anti-aliasing and left out. A turn
// looks clean when each count is under its threshold (a pen-width square, at least 6 px; two
// for the wedge) and it made no free line end. One JSON line per turn, then a summary per angle:
// turns, looks_clean_pct and how many turns show each defect.
// --png DIR: DIR/looks_NAME_DEG.png per drawing and angle size: every limb's turns as the app
// draws them, close around the joint (4 disks each side), the defects marked (spill magenta,
// wedge cyan, stray ink red, broken outline orange, free line ends ringed blue), the joint's
// disk circled; --whole: each
// turn's whole view instead.
#include "../model/bake_support.h"
#include "bench.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

namespace {

using namespace finbook;
using namespace finbook::model;

constexpr int kSide = 480;        // the compared pictures, px
constexpr double kMaxScale = 1.5; // the views' largest magnification of the canvas
constexpr int kCellSide = 320;    // a turn on the contact sheet

enum Class : std::uint8_t { Background, Ink, Fill, Rim };

Class classify(QRgb c)
{
    const int r = qRed(c), g = qGreen(c), b = qBlue(c);
    const int hi = std::max({r, g, b}), lo = std::min({r, g, b});
    if (hi < 110)
        return Ink;
    if (hi >= 150 && hi - lo > 0.25 * hi)
        return Fill;
    if (lo >= 247)
        return Background;
    return Rim; // grey: a line's anti-aliased edge
}

std::vector<Class> classes(const QImage &image)
{
    std::vector<Class> out(std::size_t(image.width()) * std::size_t(image.height()));
    for (int y = 0; y < image.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            out[std::size_t(y) * std::size_t(image.width()) + std::size_t(x)] = classify(row[x]);
    }
    return out;
}

// Distance (px, 3-4 chamfer) from every pixel to the nearest set one of `mask`.
std::vector<float> distanceTo(const std::vector<bool> &mask, int w, int h)
{
    constexpr float kFar = 1e9f;
    std::vector<float> d(mask.size(), kFar);
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i])
            d[i] = 0.0f;
    const auto at = [&](int x, int y) -> float & { return d[std::size_t(y) * std::size_t(w) + x]; };
    const float a = 1.0f, b = std::numbers::sqrt2_v<float>;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float &v = at(x, y);
            if (x > 0)
                v = std::min(v, at(x - 1, y) + a);
            if (y > 0) {
                v = std::min(v, at(x, y - 1) + a);
                if (x > 0)
                    v = std::min(v, at(x - 1, y - 1) + b);
                if (x + 1 < w)
                    v = std::min(v, at(x + 1, y - 1) + b);
            }
        }
    for (int y = h - 1; y >= 0; --y)
        for (int x = w - 1; x >= 0; --x) {
            float &v = at(x, y);
            if (x + 1 < w)
                v = std::min(v, at(x + 1, y) + a);
            if (y + 1 < h) {
                v = std::min(v, at(x, y + 1) + a);
                if (x + 1 < w)
                    v = std::min(v, at(x + 1, y + 1) + b);
                if (x > 0)
                    v = std::min(v, at(x - 1, y + 1) + b);
            }
        }
    return d;
}

// `path` (non-zero rule) through `t` on a kSide square: white inside, black outside.
QImage pathMask(QPainterPath path, const QTransform &t)
{
    QImage mask(kSide, kSide, QImage::Format_Grayscale8);
    mask.fill(0);
    QPainter painter(&mask);
    painter.setTransform(t);
    painter.setPen(Qt::NoPen);
    painter.setBrush(Qt::white);
    path.setFillRule(Qt::WindingFill);
    painter.drawPath(path);
    return mask;
}

double segmentDistance(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF q = a + t * ab - p;
    return std::hypot(q.x(), q.y());
}

struct Turn {
    int joint = -1; // the limb's first joint below its base
    double degrees = 0.0;
    long long spill = 0, wedge = 0, stray = 0, broken = 0;
    bool clean = true;
    bool cut = true; // every piece moved rigidly (else judged as a paper limb cut between bones)
    QImage picture;  // as the app draws it
    std::vector<std::uint8_t> marks; // per pixel: 0, or 1 spill, 2 wedge, 3 stray, 4 broken
    std::vector<QPointF> freeEnds;   // line ends the turn made near the joint, picture px
    QPointF pivot;                   // picture px
    double disk = 0.0;               // the joint's disk, picture px
};

// Marks in pieces smaller than `least` px (a speck where a thin line's anti-aliasing differs
// by a shade, not a thing the eye sees) are dropped, and the counts made again.
void dropSpecks(Turn &turn, int w, int h, double least)
{
    std::vector<std::uint8_t> &marks = turn.marks;
    std::vector<bool> seen(marks.size(), false);
    std::vector<std::size_t> piece, stack;
    for (std::size_t start = 0; start < marks.size(); ++start) {
        if (!marks[start] || seen[start])
            continue;
        piece.clear();
        stack.assign(1, start);
        seen[start] = true;
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            piece.push_back(i);
            const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= w || v >= h)
                        continue;
                    const std::size_t n = std::size_t(v) * std::size_t(w) + std::size_t(u);
                    if (!seen[n] && marks[n] == marks[start]) {
                        seen[n] = true;
                        stack.push_back(n);
                    }
                }
        }
        if (double(piece.size()) < least)
            for (const std::size_t i : piece)
                marks[i] = 0;
    }
    turn.spill = turn.wedge = turn.stray = turn.broken = 0;
    for (const std::uint8_t m : marks) {
        turn.spill += m == 1;
        turn.wedge += m == 2;
        turn.stray += m == 3;
        turn.broken += m == 4;
    }
}

struct Summary {
    int turns = 0, clean = 0, spill = 0, wedge = 0, stray = 0, broken = 0, freeEnds = 0, failed = 0;
};

void print(const QJsonObject &row)
{
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

// Each pixel's nearest bone (by its child joint; −1 for the background) in a view.
std::vector<int> nearestBones(const std::vector<Class> &restClass, const QTransform &t,
                              const SkeletonRig &skeleton)
{
    std::vector<QPointF> joints;
    for (const QPointF &p : skeleton.joints)
        joints.push_back(t.map(p));
    std::vector<int> out(restClass.size(), -1);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(kSide) + std::size_t(x);
            if (restClass[i] == Background)
                continue;
            double best = std::numeric_limits<double>::infinity();
            for (int k = 0; k < skeleton.jointCount(); ++k) {
                const int p = skeleton.parent[std::size_t(k)];
                if (p < 0)
                    continue;
                const double d = segmentDistance(QPointF(x + 0.5, y + 0.5), joints[std::size_t(p)],
                                                 joints[std::size_t(k)]);
                if (d < best) {
                    best = d;
                    out[i] = k;
                }
            }
        }
    return out;
}

// The limbs bake turns: joints whose parent is a limb base (without any, the root's children).
std::vector<int> limbJoints(const SkeletonRig &s)
{
    bool anyBase = false;
    for (int j = 0; j < s.jointCount(); ++j)
        anyBase = anyBase || s.isLimbBase(j);
    std::vector<int> out;
    for (int j = 0; j < s.jointCount(); ++j) {
        const int parent = s.parent[std::size_t(j)];
        if (anyBase ? parent >= 0 && s.isLimbBase(parent) : parent >= 0 && parent == s.root)
            out.push_back(j);
    }
    return out;
}

bool below(const SkeletonRig &s, int k, int j)
{
    for (; k >= 0; k = s.parent[std::size_t(k)])
        if (k == j)
            return true;
    return false;
}

void judgeFile(const QString &file, const std::vector<double> &degrees, const QString &pngDir,
               bool whole, std::map<double, Summary> &summaries)
{
    const QString name = QFileInfo(file).completeBaseName();
    QString error;
    const auto lines = testing::readDrawing(file, &error);
    if (!error.isEmpty()) {
        print({{QStringLiteral("bench"), QStringLiteral("looks")},
               {QStringLiteral("file"), QFileInfo(file).fileName()},
               {QStringLiteral("error"), error}});
        return;
    }
    Document doc;
    const Id g = testing::drawingDocument(doc, lines);
    if (g == kNoId || doc.group(g)->strokes.empty())
        return;
    const double closeGap = doc.settings().closeGap;
    const auto built = buildSkeletonRig(*doc.group(g), {}, std::nullopt, closeGap);
    if (!built || built->jointCount() < 2)
        return;
    Rig rig;
    rig.skeleton = *built;
    rig.skeleton.mode = SkinningMode::CutOut;
    rig.skeleton.angles.assign(std::size_t(built->jointCount()), 0.0);
    const std::vector<int> limbs = limbJoints(rig.skeleton);
    if (limbs.empty())
        return;

    // Per limb, the view: a square around its pivot that holds the limb in every turn (a turn
    // keeps each point's distance from the pivot), the pen at least 2 px where it can be; and
    // the rest picture in it.
    const SkeletonRig &skeleton = rig.skeleton;
    const int w = kSide, h = kSide;
    const auto index = [w](int x, int y) {
        return std::size_t(y) * std::size_t(w) + std::size_t(x);
    };
    const auto radiusAt = [&](int k) {
        return std::size_t(k) < skeleton.radius.size() ? skeleton.radius[std::size_t(k)] : 0.0;
    };
    struct View {
        QTransform t;
        double scale = 1.0;
        std::vector<Class> restClass;
        QImage restPicture;
        std::vector<int> nearestBone; // made when a turn first needs it
    };
    std::vector<View> views;
    for (const int j : limbs) {
        const int base = skeleton.parent[std::size_t(j)];
        const QPointF pivot = skeleton.joints[std::size_t(base)];
        double reach = 3.0 * radiusAt(base);
        for (int k = 0; k < skeleton.jointCount(); ++k)
            if (below(skeleton, k, j))
                reach = std::max(reach, QLineF(pivot, skeleton.joints[std::size_t(k)]).length() +
                                            radiusAt(k));
        reach = std::max(reach + 2.0 * testing::kDrawingPenWidth, (kSide - 20) / (2.0 * kMaxScale));
        View view;
        view.t = testing::pictureView(
            QRectF(pivot - QPointF(reach, reach), QSizeF(2.0 * reach, 2.0 * reach)), kSide);
        view.scale = std::sqrt(std::abs(view.t.determinant()));
        view.restPicture = testing::framePicture(doc, 0, view.t, kSide);
        view.restClass = classes(view.restPicture);
        views.push_back(std::move(view));
    }

    // One setup for every pose (the cut and the factorization depend on the rest only).
    doc.setRig(g, rig);
    DeformJob job;
    job.groupId = g;
    job.key = MeshKey::of(*doc.group(g), closeGap);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    if (!setup) {
        print({{QStringLiteral("bench"), QStringLiteral("looks")},
               {QStringLiteral("file"), QFileInfo(file).fileName()},
               {QStringLiteral("error"), setup.error()}});
        return;
    }

    std::map<double, std::vector<Turn>> turnsBySize;
    for (std::size_t l = 0; l < limbs.size(); ++l) {
        const int j = limbs[l];
        const int base = skeleton.parent[std::size_t(j)];
        const QTransform &t = views[l].t;
        const double scale = views[l].scale;
        const std::vector<Class> &restClass = views[l].restClass;
        const double pen = testing::kDrawingPenWidth * scale;
        const double tol = std::max(2.0, pen);
        const double area = std::max(6.0, pen * pen); // a pen-width square
        const QPointF pivot = t.map(skeleton.joints[std::size_t(base)]);
        const double disk = scale * radiusAt(base);
        for (const double deg : degrees) {
            Rig posed = rig;
            posed.skeleton.angles[std::size_t(j)] = deg * std::numbers::pi / 180.0;
            doc.setRig(g, posed);
            Turn turn;
            turn.joint = j;
            turn.degrees = deg;
            turn.pivot = pivot;
            turn.disk = disk;
            Summary &summary = summaries[deg];
            const auto solved = solvePose(**setup, *doc.group(g));
            if (!solved) {
                ++summary.failed;
                continue;
            }
            doc.setDeformed(g, solved->strokes);
            turn.picture = testing::framePicture(doc, 0, t, kSide);
            const std::vector<Class> shown = classes(turn.picture);
            // The paper cut-out of the app's own cut: each piece (the roots' first, then each
            // cut's, each over the ones before) shows the rest picture moved by its motion. A
            // piece that did not move rigidly (a limb not cut at its base) is judged as a
            // paper limb cut where the bones meet: nearest a bone of the turned limb, or not.
            const DeformedStrokes &layers = *doc.group(g)->deformed;
            const RigidMotion limbMotion = posed.skeleton.boneMotions()[std::size_t(j)];
            const QTransform inverse = t.inverted();
            std::vector<QPainterPath> outlines;
            outlines.push_back(layers.body);
            outlines.insert(outlines.end(), layers.pieces.begin(), layers.pieces.end());
            // Each layer's rest ink: the segments of the strokes with an end that moved with it.
            const StrokeGroup &group = *doc.group(g);
            std::vector<QImage> restInk(outlines.size());
            for (std::size_t k = 0; k < outlines.size(); ++k) {
                restInk[k] = QImage(w, h, QImage::Format_Grayscale8);
                restInk[k].fill(0);
            }
            for (std::size_t st = 0; st < group.strokes.size() && st < layers.pieceOf.size();
                 ++st) {
                const auto &points = group.strokes[st].data->points;
                const auto &piece = layers.pieceOf[st];
                if (piece.size() != points.size())
                    continue;
                const auto draw = [&](std::size_t layer, QPointF from, QPointF to) {
                    if (layer >= restInk.size())
                        return;
                    QPainter painter(&restInk[layer]);
                    painter.setRenderHint(QPainter::Antialiasing);
                    painter.setTransform(t);
                    painter.setPen(QPen(Qt::white, group.strokes[st].data->width, Qt::SolidLine,
                                        Qt::RoundCap, Qt::RoundJoin));
                    painter.drawLine(from, to);
                };
                for (std::size_t k = 0; k + 1 < points.size(); ++k) {
                    const QPointF from(points[k].x, points[k].y),
                        to(points[k + 1].x, points[k + 1].y);
                    const std::size_t a = std::size_t(piece[k] + 1),
                                      b = std::size_t(piece[k + 1] + 1);
                    if (a == b) {
                        draw(a, from, to);
                        continue;
                    }
                    // A segment across a cut: each layer shows its part, up to where the app
                    // splits it (nearest the cut's joint: cutOutSeam), or else half way.
                    QPointF split = 0.5 * (from + to);
                    if (const auto seam = cutOutSeam(group, st, k);
                        seam && a < layers.motions.size() && layers.motions[a])
                        split = layers.motions[a]->inverted().map(
                            QPointF(seam->arc.front().x, seam->arc.front().y));
                    draw(a, from, split);
                    draw(b, split, to);
                }
            }
            turn.cut = !layers.pieces.empty();
            std::vector<Class> ideal(shown.size(), Background);
            // Per pixel, the rest pixel that its fill (idealFrom) or its line (inkFrom) shows.
            std::vector<std::size_t> idealFrom(shown.size(), std::size_t(-1)),
                inkFrom(shown.size(), std::size_t(-1));
            std::vector<bool> allowed(shown.size(), false);
            std::vector<int> pieceAt(shown.size(), -1); // the topmost layer over each pixel
            const auto restAt = [&](QPointF from) {
                const int fx = int(std::floor(from.x())), fy = int(std::floor(from.y()));
                return fx < 0 || fy < 0 || fx >= w || fy >= h ? std::size_t(-1) : index(fx, fy);
            };
            for (std::size_t k = 0; k < outlines.size(); ++k) {
                const QImage mask = pathMask(outlines[k], t);
                const bool rigid = k < layers.motions.size() && layers.motions[k].has_value();
                const QTransform back =
                    rigid ? inverse * layers.motions[k]->inverted() * t : QTransform();
                for (int y = 0; y < h; ++y) {
                    const uchar *row = mask.constScanLine(y);
                    for (int x = 0; x < w; ++x) {
                        const std::size_t i = index(x, y);
                        const std::size_t r =
                            rigid ? restAt(back.map(QPointF(x + 0.5, y + 0.5))) : std::size_t(-1);
                        if (row[x] > 127) {
                            pieceAt[i] = int(k);
                            allowed[i] = true;
                            // The layer's fills: the rest fill moved with it, over the layers
                            // below (where it has none they show through).
                            if (r != std::size_t(-1) && restClass[r] == Fill) {
                                ideal[i] = Fill;
                                idealFrom[i] = r;
                            }
                        }
                        // Its lines, wherever they reach.
                        if (r != std::size_t(-1) &&
                            restInk[k].constScanLine(int(r / std::size_t(w)))[r % std::size_t(w)] >
                                145) {
                            ideal[i] = Ink;
                            inkFrom[i] = r;
                        }
                    }
                }
            }
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = index(x, y);
                    const int k = pieceAt[i];
                    if (k < 0 || (std::size_t(k) < layers.motions.size() && layers.motions[k]))
                        continue;
                    // A piece that did not move rigidly: the paper limb cut where the bones
                    // meet, over the body.
                    turn.cut = false;
                    if (views[l].nearestBone.empty())
                        views[l].nearestBone = nearestBones(restClass, t, skeleton);
                    const std::vector<int> &nearestBone = views[l].nearestBone;
                    const QPointF q(x + 0.5, y + 0.5);
                    const std::size_t r = restAt(t.map(limbMotion.unmap(inverse.map(q))));
                    if (r != std::size_t(-1) && restClass[r] != Background &&
                        below(skeleton, nearestBone[r], j))
                        ideal[i] = restClass[r];
                    else if (!below(skeleton, nearestBone[i], j))
                        ideal[i] = restClass[i];
                    else
                        ideal[i] = Background;
                }
            // A piece's line that the pose laid inside one colour (an arm of the body's colour
            // turned in over it): the paper shows that colour all round it, and at rest the
            // colour lay on one side of it only. Where the pieces are of one colour the eye sees
            // one shape, with no line there (and no stub where it would end at the joint).
            {
                const QRgb *restPixels =
                    reinterpret_cast<const QRgb *>(views[l].restPicture.constBits());
                const auto sameColour = [](QRgb a, QRgb b) {
                    return std::abs(qRed(a) - qRed(b)) <= 24 &&
                           std::abs(qGreen(a) - qGreen(b)) <= 24 &&
                           std::abs(qBlue(a) - qBlue(b)) <= 24;
                };
                const double rho = pen + 1.5; // past the line from any of its pixels
                constexpr int kRing = 12;
                std::vector<std::size_t> merged, oneColour;
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const std::size_t i = index(x, y);
                        if (ideal[i] != Ink || inkFrom[i] == std::size_t(-1))
                            continue;
                        // Round it as the paper shows it: fill everywhere not ink, of one colour
                        // (but for two points on an anti-aliased rim).
                        std::vector<QRgb> seen;
                        bool filled = true;
                        for (int k = 0; k < kRing && filled; ++k) {
                            const double a = 2.0 * std::numbers::pi * k / kRing;
                            const std::size_t q = restAt(
                                QPointF(x + 0.5 + rho * std::cos(a), y + 0.5 + rho * std::sin(a)));
                            if (q == std::size_t(-1) || ideal[q] == Background)
                                filled = false;
                            else if (ideal[q] == Fill && idealFrom[q] != std::size_t(-1))
                                seen.push_back(restPixels[idealFrom[q]]);
                        }
                        if (!filled || seen.size() < std::size_t(kRing / 2))
                            continue;
                        std::optional<QRgb> colour;
                        for (const QRgb c : seen)
                            if (std::count_if(seen.begin(), seen.end(),
                                              [&](QRgb d) { return sameColour(c, d); }) +
                                    2 >=
                                std::ptrdiff_t(seen.size()))
                                colour = c;
                        if (!colour)
                            continue;
                        // Round it at rest: that colour on one side, something else on the other.
                        const std::size_t r = inkFrom[i];
                        const double rx = double(r % std::size_t(w)) + 0.5,
                                     ry = double(r / std::size_t(w)) + 0.5;
                        bool in = false, out = false;
                        for (int k = 0; k < kRing; ++k) {
                            const double a = 2.0 * std::numbers::pi * k / kRing;
                            const std::size_t q =
                                restAt(QPointF(rx + rho * std::cos(a), ry + rho * std::sin(a)));
                            if (q == std::size_t(-1) || restClass[q] == Background)
                                out = true;
                            else if (restClass[q] == Fill)
                                (sameColour(restPixels[q], *colour) ? in : out) = true;
                        }
                        (in && out ? merged : oneColour).push_back(i);
                    }
                // A pixel of one colour all round that lies along a merged line is of it too
                // (the rest test misses pixels here and there on a traced outline's steps).
                std::vector<bool> isMerged(shown.size(), false);
                for (const std::size_t i : merged)
                    isMerged[i] = true;
                const std::vector<float> toMerged = distanceTo(isMerged, w, h);
                for (const std::size_t i : oneColour)
                    if (toMerged[i] <= 2.0 * pen)
                        merged.push_back(i);
                for (const std::size_t i : merged)
                    ideal[i] = Fill;
            }
            // The sockets: round ends in the limb's fill (filled, and a line may run round
            // their edge).
            std::vector<bool> inSocket(shown.size(), false);
            for (const QPainterPath &socket : layers.sockets) {
                if (socket.isEmpty())
                    continue;
                const QImage mask = pathMask(socket, t);
                for (int y = 0; y < h; ++y) {
                    const uchar *row = mask.constScanLine(y);
                    for (int x = 0; x < w; ++x)
                        if (row[x] > 127)
                            inSocket[index(x, y)] = true;
                }
            }
            const std::vector<float> toSocket = distanceTo(inSocket, w, h);
            // A socket's round edge, where a piece's line may run round the joint (its inside is
            // fill: a line across it is a chord through the joint).
            std::vector<bool> socketEdge(shown.size(), false);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (inSocket[index(x, y)])
                        for (const auto &[dx, dy] : {std::pair(1, 0), std::pair(-1, 0),
                                                     std::pair(0, 1), std::pair(0, -1)}) {
                            const int u = x + dx, v = y + dy;
                            if (u < 0 || v < 0 || u >= w || v >= h || !inSocket[index(u, v)])
                                socketEdge[index(x, y)] = true;
                        }
            const std::vector<float> toSocketEdge = distanceTo(socketEdge, w, h);
            const std::vector<float> toAllowed = distanceTo(allowed, w, h);
            std::vector<bool> visibleInk(shown.size());
            for (std::size_t i = 0; i < shown.size(); ++i)
                visibleInk[i] = ideal[i] == Ink;
            const std::vector<float> toInk = distanceTo(visibleInk, w, h);
            std::vector<bool> shownInk(shown.size()), idealFill(shown.size()),
                notIdealFill(shown.size());
            for (std::size_t i = 0; i < shown.size(); ++i) {
                shownInk[i] = shown[i] == Ink || shown[i] == Rim;
                idealFill[i] = ideal[i] == Fill;
                notIdealFill[i] = !idealFill[i];
            }
            const std::vector<float> toShownInk = distanceTo(shownInk, w, h);
            const std::vector<float> toOutsideFill = distanceTo(notIdealFill, w, h);
            turn.marks.assign(shown.size(), 0);
            for (std::size_t i = 0; i < shown.size(); ++i) {
                const bool nearSocket = toSocket[i] <= tol;
                if (shown[i] == Fill && !nearSocket && toAllowed[i] > tol) {
                    ++turn.spill;
                    turn.marks[i] = 1;
                } else if (shown[i] == Background && toOutsideFill[i] > tol) {
                    ++turn.wedge;
                    turn.marks[i] = 2;
                } else if (shown[i] == Ink && toInk[i] > tol && toSocketEdge[i] > tol) {
                    ++turn.stray;
                    turn.marks[i] = 3;
                } else if (ideal[i] == Ink && toShownInk[i] > tol && !nearSocket) {
                    ++turn.broken;
                    turn.marks[i] = 4;
                }
            }
            dropSpecks(turn, w, h, std::max(3.0, pen));
            // Line ends the turn made near the joint: ends of the painted runs that are neither
            // a stroke's own end nor met by another run's end, and that no fill of a layer
            // above covers (a stub or hook where a cut meets the outline).
            {
                const std::vector<PaintLayer> painted = paintLayers(group, doc.settings());
                struct End {
                    QPointF at;
                    std::size_t layer;
                };
                std::vector<End> ends;
                for (std::size_t L = 0; L < painted.size(); ++L)
                    for (const PaintItem &item : painted[L].strokes)
                        if (item.points && item.points->size() >= 2)
                            for (const StrokePoint *p :
                                 {&item.points->front(), &item.points->back()})
                                ends.push_back({QPointF(p->x, p->y), L});
                std::vector<QPointF> strokeEnds;
                for (std::size_t st = 0; st < group.strokes.size(); ++st) {
                    const std::vector<StrokePoint> &shownPoints = displayedPoints(group, st);
                    if (shownPoints.empty())
                        continue;
                    strokeEnds.emplace_back(shownPoints.front().x, shownPoints.front().y);
                    strokeEnds.emplace_back(shownPoints.back().x, shownPoints.back().y);
                }
                const QPointF joint = skeleton.joints[std::size_t(base)];
                const double near = std::max(3.0 * radiusAt(base), 10.0);
                // Whether an end shows as one in the picture: on ink, with the ink crossing a
                // circle round it (two pens out) once, where a line that goes on crosses it
                // twice and a line hidden under a fill not at all.
                const auto looksLikeAnEnd = [&](QPointF canvas) {
                    const QPointF c = t.map(canvas);
                    const auto inkAt = [&](QPointF q) {
                        const int x = int(std::floor(q.x())), y = int(std::floor(q.y()));
                        return x >= 0 && y >= 0 && x < w && y < h &&
                               (shown[index(x, y)] == Ink || shown[index(x, y)] == Rim);
                    };
                    if (!inkAt(c))
                        return false;
                    const double rho = std::max(4.0, 2.0 * pen);
                    constexpr int kSamples = 64;
                    int crossings = 0;
                    bool previous = inkAt(c + QPointF(rho, 0.0));
                    for (int k = 1; k <= kSamples; ++k) {
                        const double a = 2.0 * std::numbers::pi * k / kSamples;
                        const bool here = inkAt(c + rho * QPointF(std::cos(a), std::sin(a)));
                        crossings += here && !previous;
                        previous = here;
                    }
                    return crossings == 1;
                };
                for (const End &end : ends) {
                    if (QLineF(end.at, joint).length() > near ||
                        std::any_of(strokeEnds.begin(), strokeEnds.end(),
                                    [&](QPointF q) { return QLineF(end.at, q).length() <= 0.5; }))
                        continue;
                    if (looksLikeAnEnd(end.at) &&
                        std::none_of(turn.freeEnds.begin(), turn.freeEnds.end(), [&](QPointF q) {
                            return QLineF(q, t.map(end.at)).length() < pen;
                        }))
                        turn.freeEnds.push_back(t.map(end.at));
                }
            }
            const bool spill = turn.spill > area, wedge = turn.wedge > 2.0 * area,
                       stray = turn.stray > area, broken = turn.broken > area,
                       freeEnds = !turn.freeEnds.empty();
            turn.clean = !spill && !wedge && !stray && !broken && !freeEnds;
            summary.freeEnds += freeEnds;
            ++summary.turns;
            summary.clean += turn.clean;
            summary.spill += spill;
            summary.wedge += wedge;
            summary.stray += stray;
            summary.broken += broken;
            print({{QStringLiteral("bench"), QStringLiteral("looks")},
                   {QStringLiteral("file"), QFileInfo(file).fileName()},
                   {QStringLiteral("joint"), j},
                   {QStringLiteral("degrees"), deg},
                   {QStringLiteral("spill_px"), double(turn.spill)},
                   {QStringLiteral("wedge_px"), double(turn.wedge)},
                   {QStringLiteral("stray_px"), double(turn.stray)},
                   {QStringLiteral("broken_px"), double(turn.broken)},
                   {QStringLiteral("free_ends"), int(turn.freeEnds.size())},
                   {QStringLiteral("pen_px"), pen},
                   {QStringLiteral("cut"), turn.cut},
                   {QStringLiteral("looks_clean"), turn.clean}});
            if (!pngDir.isEmpty())
                turnsBySize[std::abs(deg)].push_back(std::move(turn));
        }
    }
    if (pngDir.isEmpty())
        return;
    for (auto &[size, turns] : turnsBySize) {
        const int columns = 4;
        const int rows = (int(turns.size()) + columns - 1) / columns;
        const int cellSide = whole ? kSide : kCellSide; // a whole view at its own size
        QImage sheet(columns * cellSide, rows * cellSide, QImage::Format_RGB32);
        sheet.fill(Qt::white);
        QPainter painter(&sheet);
        painter.setRenderHint(QPainter::Antialiasing);
        for (std::size_t n = 0; n < turns.size(); ++n) {
            Turn &turn = turns[n];
            static const QRgb kMark[] = {0, qRgb(230, 0, 230), qRgb(0, 200, 230), qRgb(230, 0, 0),
                                         qRgb(255, 140, 0)};
            QImage marked = turn.picture.convertToFormat(QImage::Format_RGB32);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (const std::uint8_t m = turn.marks[index(x, y)])
                        marked.setPixel(x, y, kMark[m]);
            const QRectF cell((int(n) % columns) * cellSide, (int(n) / columns) * cellSide,
                              cellSide, cellSide);
            // The joint, close: 4 disks (at least 50 px) each side of the pivot.
            const double half = whole ? kSide / 2.0 : std::max(50.0, 4.0 * turn.disk);
            const QRectF source(turn.pivot - QPointF(half, half), QSizeF(2 * half, 2 * half));
            painter.drawImage(cell, marked, source);
            const double k = double(cellSide) / (2 * half);
            painter.setPen(QPen(QColor(0, 160, 0), 1));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(cell.center(), turn.disk * k, turn.disk * k);
            painter.setPen(QPen(QColor(0, 90, 255), 2));
            for (const QPointF &end : turn.freeEnds)
                painter.drawEllipse(cell.center() + (end - turn.pivot) * k, 6.0, 6.0);
            painter.setPen(turn.clean ? Qt::darkGreen : Qt::red);
            painter.drawText(cell.adjusted(4, 2, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                             QStringLiteral("joint %1 %2°%3")
                                 .arg(turn.joint)
                                 .arg(turn.degrees)
                                 .arg(turn.clean ? QString() : QStringLiteral(" ✗")));
            painter.setPen(QColor(200, 200, 200));
            painter.drawRect(cell);
        }
        painter.end();
        sheet.save(QDir(pngDir).filePath(
            QStringLiteral("looks_%1_%2.png").arg(name).arg(int(std::lround(size)))));
    }
}

int benchLooks(const QStringList &argsIn)
{
    QStringList args = argsIn;
    QString pngDir;
    bool whole = false;
    std::vector<double> degrees = {60.0, -60.0, 100.0, -100.0};
    while (args.size() >= 2 && args[0].startsWith(QLatin1String("--"))) {
        if (args[0] == QLatin1String("--whole")) {
            whole = true;
            args = args.mid(1);
            continue;
        }
        if (args[0] == QLatin1String("--png")) {
            pngDir = args[1];
            QDir().mkpath(pngDir);
        } else if (args[0] == QLatin1String("--degrees")) {
            degrees.clear();
            for (const QString &d : args[1].split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                bool ok = false;
                const double v = d.toDouble(&ok);
                if (!ok || !std::isfinite(v)) {
                    std::fprintf(stderr, "looks: bad angle %s\n", qPrintable(d));
                    return 2;
                }
                degrees.push_back(v);
            }
        } else {
            break;
        }
        args = args.mid(2);
    }
    if (args.isEmpty()) {
        std::fprintf(stderr, "looks: no drawing given\n");
        return 2;
    }
    std::map<double, Summary> summaries;
    for (const QString &file : args)
        judgeFile(file, degrees, pngDir, whole, summaries);
    for (const auto &[deg, s] : summaries)
        print({{QStringLiteral("bench"), QStringLiteral("looks_summary")},
               {QStringLiteral("degrees"), deg},
               {QStringLiteral("turns"), s.turns},
               {QStringLiteral("failed"), s.failed},
               {QStringLiteral("looks_clean_pct"),
                s.turns > 0 ? 100.0 * double(s.clean) / double(s.turns) : 0.0},
               {QStringLiteral("spill"), s.spill},
               {QStringLiteral("wedge"), s.wedge},
               {QStringLiteral("stray_ink"), s.stray},
               {QStringLiteral("broken_outline"), s.broken},
               {QStringLiteral("free_line_ends"), s.freeEnds}});
    return 0;
}

} // namespace

FINBOOK_BENCH(
    "looks",
    "[--png DIR [--whole]] [--degrees A,B,...] FILE...  (Cut-out turns judged from the picture)",
    benchLooks);
