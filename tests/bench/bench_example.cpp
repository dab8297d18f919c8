// finbook-bench example OUTFILE: writes the bundled example animation,
// resources/examples/walk.finbook — a small scene at 12 fps on a 1280×720 canvas: a background
// drawn once and exposed for the whole shot (at depth 1, so the camera's move shifts it half as
// much), a 12-frame walk cycle on its own layer, a blink on a third layer, and a camera that
// eases in on the walker.
//
// Drawn procedurally but meant to look hand-made: every stroke wobbles a little, its pressure
// swells in the middle and tapers at the ends, and the seed is fixed so the file is the same
// on every run. The ground line is one stroke shared by all frames, as duplicating a frame in
// the editor would leave it, so the example also exercises the shared stroke table.
#include "bench.h"

#include <finbook/model/finbook_file.h>

#include <QLineF>
#include <QSaveFile>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace {
using namespace finbook::model;
using Path = std::vector<QPointF>;

constexpr int kFrames = 12;
constexpr QRgb kInk = 0xff23232b;
constexpr QRgb kShirt = 0xff2f5d9e;
constexpr QRgb kBackInk = 0xff7a7a86; // limbs behind the body, drawn lighter
constexpr QRgb kEarth = 0xff6b4f2a;
constexpr double kPi = std::numbers::pi;

class Pen {
public:
    explicit Pen(unsigned seed)
        : m_rng(seed)
    {}

    // A stroke along `path`, resampled every ~2.5 px with a slow sideways wobble and jitter.
    StrokeDataPtr draw(const Path &path, QRgb color, float width)
    {
        auto data = std::make_shared<StrokeData>();
        data->color = color;
        data->width = width;
        const Path dense = resample(path, 2.5);
        const double phase1 = uniform() * 2 * kPi, phase2 = uniform() * 2 * kPi;
        for (std::size_t i = 0; i < dense.size(); ++i) {
            const double t = dense.size() > 1 ? double(i) / double(dense.size() - 1) : 0.5;
            const QPointF normal = normalAt(dense, i);
            const double wobble =
                0.9 * std::sin(t * 5.0 + phase1) + 0.4 * std::sin(t * 13.0 + phase2);
            const QPointF p = dense[i] + normal * wobble + QPointF(jitter(0.15), jitter(0.15));
            const double swell = std::pow(std::sin(kPi * std::clamp(t, 0.02, 0.98)), 0.6);
            const double pressure = std::clamp(0.3 + 0.65 * swell + jitter(0.04), 0.05, 1.0);
            data->points.push_back({float(p.x()), float(p.y()), float(pressure)});
        }
        return data;
    }

private:
    double uniform() { return double(m_rng()) / 4294967296.0; }
    double jitter(double amplitude) { return (uniform() * 2 - 1) * amplitude; }

    static Path resample(const Path &path, double step)
    {
        Path out{path.front()};
        for (std::size_t i = 1; i < path.size(); ++i) {
            const QLineF segment(path[i - 1], path[i]);
            const int n = std::max(1, int(std::ceil(segment.length() / step)));
            for (int k = 1; k <= n; ++k)
                out.push_back(segment.pointAt(double(k) / n));
        }
        return out;
    }
    static QPointF normalAt(const Path &p, std::size_t i)
    {
        const QPointF d = p[std::min(i + 1, p.size() - 1)] - p[i > 0 ? i - 1 : 0];
        const double len = std::hypot(d.x(), d.y());
        return len > 0 ? QPointF(-d.y() / len, d.x() / len) : QPointF();
    }

    std::mt19937 m_rng;
};

QPointF polar(QPointF from, double degreesFromDown, double length)
{
    const double a = degreesFromDown * kPi / 180.0;
    return from + QPointF(std::sin(a) * length, std::cos(a) * length);
}

Path arc(QPointF centre, double rx, double ry, double fromDeg, double toDeg)
{
    Path p;
    for (int i = 0; i <= 48; ++i) {
        const double a = (fromDeg + (toDeg - fromDeg) * i / 48.0) * kPi / 180.0;
        p.push_back(centre + QPointF(std::cos(a) * rx, std::sin(a) * ry));
    }
    return p;
}

// Both outlines of a two-segment limb of `thickness`, plus an end stroke (foot or hand).
struct Limb {
    QPointF root, joint, end;
};

std::vector<StrokeDataPtr> drawLimb(Pen &pen, const Limb &l, double thickness, QRgb color,
                                    const Path &extremity)
{
    auto offsetPath = [&](double side) {
        Path p;
        for (QPointF q : {l.root, l.joint, l.end}) {
            const QPointF d = l.end - l.root;
            const double len = std::hypot(d.x(), d.y());
            p.push_back(q + QPointF(-d.y() / len, d.x() / len) * side * thickness / 2);
        }
        return p;
    };
    return {pen.draw(offsetPath(1), color, 3.2f), pen.draw(offsetPath(-1), color, 3.2f),
            pen.draw(extremity, color, 3.6f)};
}

// Ids from 1 in drawing order, the walk cycle first: its frames keep the ids they had when the
// example was one layer (tests/data/walk_v1.finbook holds the same drawings).
struct Ids {
    Id next = 1;
    Id operator()() { return next++; }
};

StrokeGroup object(Ids &ids, const char *name, std::vector<StrokeDataPtr> strokes)
{
    StrokeGroup g;
    g.id = ids();
    g.name = QString::fromUtf8(name);
    for (auto &s : strokes)
        g.strokes.push_back({ids(), std::move(s)});
    return g;
}

struct Pose {
    QPointF hip, neck, head;
    Limb leftLeg, rightLeg, leftArm, rightArm;
};

// Legs swing ±26°, arms against them; the body is highest when the legs pass each other.
Pose poseAt(int frame)
{
    const double phase = 2 * kPi * frame / kFrames;
    const double swing = std::sin(phase);
    Pose p;
    p.hip = QPointF(640, 420 - 10 * std::cos(2 * phase));
    p.neck = p.hip + QPointF(12, -150);
    p.head = p.neck + QPointF(8, -58);
    auto leg = [&](double s) {
        const QPointF knee = polar(p.hip, -26 * s, 105);
        const double bend = s > 0 ? 6 + 30 * s : 6; // the trailing leg lifts its foot
        return Limb{p.hip, knee, polar(knee, -26 * s - bend, 105)};
    };
    auto arm = [&](double s) {
        const QPointF shoulder = p.neck + QPointF(0, 22);
        const QPointF elbow = polar(shoulder, 22 * s, 72);
        return Limb{shoulder, elbow, polar(elbow, 22 * s + 28, 66)};
    };
    p.leftLeg = leg(swing);
    p.rightLeg = leg(-swing);
    p.leftArm = arm(-swing);
    p.rightArm = arm(swing);
    return p;
}

std::vector<StrokeDataPtr> drawLeg(Pen &pen, const Limb &leg, QRgb color)
{
    return drawLimb(pen, leg, 26, color, {leg.end + QPointF(-10, 0), leg.end + QPointF(26, 2)});
}

std::vector<StrokeDataPtr> drawArm(Pen &pen, const Limb &arm, QRgb color)
{
    return drawLimb(pen, arm, 18, color, arc(arm.end + QPointF(2, 6), 9, 9, 0, 340));
}

Frame drawFrame(Ids &doc, Pen &pen, int f, const StrokeDataPtr &groundLine)
{
    const Pose p = poseAt(f);
    Frame frame;
    frame.id = doc();
    // Grass tufts slide left so the character seems to walk while staying centred.
    std::vector<StrokeDataPtr> ground{groundLine};
    for (int i = 0; i < 8; ++i) {
        const double x = std::fmod(1400.0 + i * 175.0 - f * 22.0, 1400.0) - 60;
        ground.push_back(pen.draw({{x, 641}, {x + 6, 628}, {x + 10, 641}}, kEarth, 2.0f));
    }
    frame.groups.push_back(object(doc, "ground", ground));
    frame.groups.push_back(object(doc, "right arm", drawArm(pen, p.rightArm, kBackInk)));
    frame.groups.push_back(object(doc, "right leg", drawLeg(pen, p.rightLeg, kBackInk)));
    const QPointF h = p.hip, n = p.neck;
    frame.groups.push_back(
        object(doc, "torso",
               {pen.draw({n + QPointF(-30, 8), h + QPointF(-24, 0), h + QPointF(24, 0),
                          n + QPointF(30, 8)},
                         kShirt, 4.0f),
                pen.draw(arc(n + QPointF(0, 6), 30, 12, 200, 340), kShirt, 3.0f),
                pen.draw({h + QPointF(-24, -24), h + QPointF(24, -24)}, kInk, 2.5f)}));
    frame.groups.push_back(
        object(doc, "head",
               {pen.draw(arc(p.head, 40, 46, -80, 270), kInk, 3.5f),
                pen.draw({p.head + QPointF(18, -8), p.head + QPointF(19, -4)}, kInk, 5.0f),
                pen.draw(arc(p.head + QPointF(16, 16), 12, 6, 10, 150), kInk, 2.5f),
                pen.draw(arc(p.head + QPointF(-6, -36), 34, 14, 180, 340), kInk, 3.0f)}));
    frame.groups.push_back(object(doc, "left leg", drawLeg(pen, p.leftLeg, kInk)));
    frame.groups.push_back(object(doc, "left arm", drawArm(pen, p.leftArm, kInk)));
    return frame;
}

// The background: hills, a house and the sun, drawn once.
Frame drawBackground(Ids &ids, Pen &pen)
{
    Frame frame;
    frame.id = ids();
    frame.hold = kFrames; // the whole shot
    frame.groups.push_back(
        object(ids, "hills",
               {pen.draw({{0, 520}, {220, 470}, {420, 505}, {700, 455}, {980, 500}, {1280, 470}},
                         kBackInk, 2.5f)}));
    const QPointF base(930, 520);
    frame.groups.push_back(object(
        ids, "house",
        {pen.draw(
             {base, base + QPointF(0, -120), base + QPointF(170, -120), base + QPointF(170, 0)},
             kInk, 3.0f),
         pen.draw({base + QPointF(-20, -115), base + QPointF(85, -200), base + QPointF(190, -115)},
                  kEarth, 3.5f),
         pen.draw({base + QPointF(70, 0), base + QPointF(70, -60), base + QPointF(105, -60),
                   base + QPointF(105, 0)},
                  kEarth, 2.5f),
         pen.draw({base + QPointF(20, -95), base + QPointF(50, -95), base + QPointF(50, -70),
                   base + QPointF(20, -70), base + QPointF(20, -95)},
                  kShirt, 2.0f)}));
    frame.groups.push_back(
        object(ids, "sun", {pen.draw(arc({200, 150}, 45, 45, 0, 360), 0xffe0a020, 4.0f)}));
    return frame;
}

// A blink: eyelids over the eye on two frames, nothing before or after.
std::vector<Frame> drawBlink(Ids &ids, Pen &pen)
{
    constexpr int kFirst = 7; // the frames the eyes are shut
    std::vector<Frame> cels;
    Frame before;
    before.id = ids();
    before.hold = kFirst;
    cels.push_back(std::move(before));
    for (int f = kFirst; f < kFirst + 2; ++f) {
        const QPointF eye = poseAt(f).head + QPointF(18, -6);
        Frame shut;
        shut.id = ids();
        shut.groups.push_back(
            object(ids, "eyelid",
                   {pen.draw({eye + QPointF(-4, -3), eye + QPointF(5, -3)}, 0xffffffff, 9.0f),
                    pen.draw({eye + QPointF(-6, 0), eye + QPointF(0, 2), eye + QPointF(6, 0)}, kInk,
                             2.5f)}));
        cels.push_back(std::move(shut));
    }
    Frame after;
    after.id = ids();
    after.hold = kFrames - kFirst - 2;
    cels.push_back(std::move(after));
    return cels;
}

int benchExample(const QStringList &args)
{
    if (args.size() != 1) {
        std::fprintf(stderr, "usage: finbook-bench example OUTFILE\n");
        return 2;
    }
    Ids ids;
    Pen pen(20240611);
    const StrokeDataPtr groundLine = pen.draw({{40, 642}, {640, 645}, {1240, 641}}, kEarth, 3.0f);
    std::vector<Frame> frames;
    for (int f = 0; f < kFrames; ++f)
        frames.push_back(drawFrame(ids, pen, f, groundLine));
    std::vector<Layer> layers(3);
    layers[1].id = ids();
    layers[1].properties.name = QStringLiteral("Walk");
    layers[1].cels = std::move(frames);
    layers[0].id = ids();
    layers[0].properties.name = QStringLiteral("Background");
    layers[0].properties.depth = 1.0;
    layers[0].cels.push_back(drawBackground(ids, pen));
    layers[2].id = ids();
    layers[2].properties.name = QStringLiteral("Blink");
    layers[2].cels = drawBlink(ids, pen);
    DocumentSettings settings; // 1280×720, white, 12 fps, looping
    Document doc;
    doc.reset(std::move(layers), settings, ids.next);
    // The camera eases in on the walker over the cycle.
    CameraKey from, to;
    from.center = QPointF(640, 360);
    from.easing = CameraEasing::EaseInOut;
    to.tick = kFrames - 1;
    to.center = QPointF(700, 400);
    to.zoom = 1.25;
    doc.setCamera(CameraTrack{{from, to}});
    // Not saveFinbook: regenerating the example must not leave a backup beside it.
    const QByteArray bytes = serializeFinbook(doc);
    if (auto check = readFinbook(bytes); !check) {
        std::fprintf(stderr, "%s\n", qPrintable(check.error().message));
        return 1;
    }
    QSaveFile file(args.first());
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(args.first()),
                     qPrintable(file.errorString()));
        return 1;
    }
    std::printf("{\"bench\":\"example\",\"layers\":%d,\"frames\":%d,\"points\":%lld}\n",
                doc.layerCount(), doc.frameCount(), doc.pointCount());
    return 0;
}
} // namespace

FINBOOK_BENCH("example", "OUTFILE (writes the bundled walk-cycle example)", benchExample);
