// Generated .finbook files of deep and wide structures: the shapes that cost a reader stack or
// time in proportion to a depth or a product (join chains, long bone chains, many parts on one
// big skeleton, long holds, one stroke drawn many times). They are far larger than libFuzzer's
// 64 KiB inputs, so the fuzz target's structure-aware mode (tests/fuzz/fuzz_deep.cpp) and the
// tests build them here from a few parameters.
#pragma once

#include <finbook/model/finbook_file.h>

#include <QByteArray>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace deep_build {

using namespace finbook::model;

enum class Shape : std::uint8_t {
    JoinChain,  // n objects in one frame, each a one-joint skeleton joined to the next
    JoinStar,   // one skeleton of n joints (a chain), `parts` objects joined to it
    JointChain, // one object whose skeleton is a single chain of n joints (bones)
    JointStar,  // one object whose skeleton has n joints all children of the root
    JoinTree,   // n objects joined in a binary tree (object i hangs from object (i − 1) / 2)
    Holds,      // n frames each held for the longest hold
    Repeats,    // one stroke referenced n times by one object
    Layers,     // n layers (past the 1,000 a file may hold when n says so), each of 1 to 8 cels
                // with random holds (up to the longest when posed), and random properties
                // (with `star`, depths and opacities past their limits)
    Count
};

struct Params {
    Shape shape = Shape::JoinChain;
    int n = 1000;
    int parts = 0;          // JoinStar: objects hanging from the big skeleton
    std::uint32_t seed = 1; // jitters coordinates (and decides join points and angles)
    bool posed = false;     // non-zero angles, so forward kinematics and anchors move
    bool reversed = false;  // joins point backwards (object i hangs from i − 1)
    // JoinStar: the big skeleton is a star (every bone from one root) and every part hangs at
    // its centre, equally near all bones: the worst case of finding the bone a part hangs from.
    bool star = false;
};

namespace detail {
// A small deterministic generator (xorshift32): the same parameters give the same bytes.
struct Random {
    std::uint32_t state;
    explicit Random(std::uint32_t seed)
        : state(seed == 0 ? 0x9e3779b9u : seed)
    {}
    std::uint32_t next()
    {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    }
    double unit() { return double(next() >> 8) / double(1u << 24); } // [0, 1)
};

inline SkeletonRig chainRig(int joints, QPointF from, double step, Random &random, bool posed,
                            bool star)
{
    SkeletonRig rig;
    const std::size_t n = std::size_t(std::max(1, joints));
    rig.joints.resize(n);
    rig.parent.resize(n);
    rig.radius.assign(n, 2.0);
    rig.angles.assign(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        const double jitter = random.unit() - 0.5;
        if (star) {
            const double a = 2.0 * M_PI * double(j) / double(n);
            rig.joints[j] =
                from +
                (j == 0 ? QPointF() : QPointF(std::cos(a), std::sin(a)) * step * (10.0 + jitter));
            rig.parent[j] = j == 0 ? -1 : 0;
        } else {
            rig.joints[j] = from + QPointF(double(j) * step, 5.0 * std::sin(double(j)) + jitter);
            rig.parent[j] = int(j) - 1;
        }
        if (posed && j > 0)
            rig.angles[j] = 0.01 * (random.unit() - 0.5);
    }
    rig.root = 0;
    return rig;
}

inline StrokeGroup part(Id id)
{
    StrokeGroup g;
    g.id = id;
    g.name = QStringLiteral("p");
    return g;
}
} // namespace detail

// The frames of a document of `p`'s shape; ids from 1.
inline std::vector<Frame> frames(const Params &p, Id &nextId)
{
    detail::Random random(p.seed);
    std::vector<Frame> out(1);
    out[0].id = nextId++;
    const int n = std::max(1, p.n);
    switch (p.shape) {
    case Shape::JoinChain:
    case Shape::JoinTree: {
        std::vector<StrokeGroup> &groups = out[0].groups;
        for (int i = 0; i < n; ++i)
            groups.push_back(detail::part(nextId++));
        for (int i = 0; i < n; ++i) {
            SkeletonRig &rig = groups[std::size_t(i)].rig.skeleton;
            const QPointF at(double(i % 1000) + random.unit(), double(i / 1000));
            rig = detail::chainRig(1, at, 1.0, random, p.posed, false);
            int parent = -1;
            if (p.shape == Shape::JoinTree)
                parent = i == 0 ? -1 : (i - 1) / 2;
            else
                parent = p.reversed ? i - 1 : (i + 1 < n ? i + 1 : -1);
            if (parent >= 0)
                rig.join = SkeletonJoin{groups[std::size_t(parent)].id, at, at};
        }
        break;
    }
    case Shape::JoinStar: {
        std::vector<StrokeGroup> &groups = out[0].groups;
        groups.push_back(detail::part(nextId++));
        groups[0].rig.skeleton = detail::chainRig(n, QPointF(0, 0), 1.0, random, p.posed, p.star);
        for (int i = 0; i < std::max(0, p.parts); ++i) {
            StrokeGroup g = detail::part(nextId++);
            const QPointF at =
                p.star ? QPointF(1e-3 * random.unit(), 0.0)
                       : QPointF(random.unit() * double(n), 5.0 * (random.unit() - 0.5));
            g.rig.skeleton = detail::chainRig(1, at, 1.0, random, false, false);
            g.rig.skeleton.join = SkeletonJoin{groups[0].id, at, at};
            groups.push_back(std::move(g));
        }
        break;
    }
    case Shape::JointChain:
    case Shape::JointStar: {
        StrokeGroup g = detail::part(nextId++);
        g.rig.skeleton =
            detail::chainRig(n, QPointF(0, 0), 0.01, random, p.posed, p.shape == Shape::JointStar);
        out[0].groups.push_back(std::move(g));
        break;
    }
    case Shape::Holds: {
        auto data = std::make_shared<StrokeData>();
        data->points = {{1, 1, 1}, {100, 50, 1}};
        out.resize(std::size_t(n));
        for (std::size_t f = 0; f < out.size(); ++f) {
            if (f > 0)
                out[f].id = nextId++;
            out[f].hold = kMaxHold;
            StrokeGroup g = detail::part(nextId++);
            g.strokes.push_back({nextId++, data});
            out[f].groups.push_back(std::move(g));
        }
        break;
    }
    case Shape::Repeats: {
        auto data = std::make_shared<StrokeData>();
        data->points = {{1, 1, 1}, {600, 300, 1}, {float(random.unit() * 600), 10, 0.5f}};
        StrokeGroup g = detail::part(nextId++);
        for (int i = 0; i < n; ++i)
            g.strokes.push_back({nextId++, data});
        out[0].groups.push_back(std::move(g));
        break;
    }
    case Shape::Layers: // layers() builds them; the frames are one layer's worth
    case Shape::Count:
        break;
    }
    return out;
}

// Shape::Layers: the layers of the document; ids from nextId.
inline std::vector<Layer> layers(const Params &p, Id &nextId)
{
    detail::Random random(p.seed);
    auto data = std::make_shared<StrokeData>();
    data->points = {{1, 1, 1}, {300, 150, 1}};
    std::vector<Layer> out(std::size_t(std::max(1, p.n)));
    for (Layer &layer : out) {
        layer.id = nextId++;
        layer.properties.name = QString(int(random.unit() * 40), QChar(u'L'));
        layer.properties.visible = random.unit() < 0.8;
        layer.properties.locked = random.unit() < 0.2;
        layer.properties.onionSkin = random.unit() < 0.5;
        // With `star`, a tenth of them outside the allowed ranges: a reader refuses them, or
        // mends them when it opens the file anyway.
        const bool wild = p.star && random.unit() < 0.1;
        layer.properties.opacity = wild ? random.unit() * 4 - 2 : random.unit();
        layer.properties.depth =
            wild ? random.unit() * 400 - 200
                 : kMinLayerDepth + random.unit() * (kMaxLayerDepth - kMinLayerDepth);
        const int cels = 1 + int(random.unit() * 8);
        for (int c = 0; c < cels; ++c) {
            Frame cel;
            cel.id = nextId++;
            cel.hold = 1 + int(random.unit() * (p.posed ? kMaxHold - 1 : 24));
            if (random.unit() < 0.7) { // else an empty stretch
                StrokeGroup g = detail::part(nextId++);
                g.strokes.push_back({nextId++, data});
                cel.groups.push_back(std::move(g));
            }
            layer.cels.push_back(std::move(cel));
        }
    }
    return out;
}

// The bytes of a current-format file of `p`'s shape (written as Finbook writes).
inline QByteArray file(const Params &p)
{
    Id next = 1;
    DocumentSettings settings;
    settings.canvasSize = QSize(640, 360);
    if (p.shape == Shape::Layers)
        return serializeFinbook(layers(p, next), settings);
    const std::vector<Frame> f = frames(p, next);
    return serializeFinbook(f, settings);
}

} // namespace deep_build
