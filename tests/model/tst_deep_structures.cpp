// Deep and wide structures from files (issue 25, items 1 and 2): 80,000 parts each joined to
// the next, 100,000-joint bone chains, thousands of parts on one huge skeleton. Opening them
// must neither exhaust the stack (joins were resolved by recursion, one frame per join) nor
// cost parts × joints (each part scanned every bone of its parent); IK drags on them stay
// bounded. The generated files are far beyond what the fuzzer's 64 KiB inputs reach.
#include "../../model/src/skeleton/join_resolution.h"
#include "../fuzz/fuzz_checks.h"
#include "deep_structures.h"

#include <finbook/deform/skeleton/inverse_kinematics.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/skeleton/skeleton_join.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <QElapsedTimer>
#include <QTest>
#include <QThread>

#include <algorithm>
#include <functional>
#include <limits>

using namespace finbook;
using namespace finbook::model;
using deep_build::Shape;

namespace {

// The recursive resolution joins had before (a reference for small frames only): anchors
// must come out exactly the same.
std::vector<SkeletonAnchor> referenceAnchors(Frame frame)
{
    const std::size_t n = frame.groups.size();
    const auto indexOf = [&](Id id) {
        for (std::size_t i = 0; i < n; ++i)
            if (frame.groups[i].id == id)
                return int(i);
        return -1;
    };
    enum State : char { Unvisited, Visiting, Done };
    std::vector<State> state(n, Unvisited);
    std::vector<SkeletonAnchor> anchors(n);
    const std::function<void(std::size_t)> resolve = [&](std::size_t i) {
        if (state[i] != Unvisited)
            return;
        state[i] = Visiting;
        SkeletonRig &rig = frame.groups[i].rig.skeleton;
        SkeletonAnchor anchor;
        if (!rig.empty() && rig.join.joined()) {
            const int p = indexOf(rig.join.parent);
            if (p >= 0 && std::size_t(p) != i && state[std::size_t(p)] != Visiting) {
                resolve(std::size_t(p));
                const SkeletonRig &parent = frame.groups[std::size_t(p)].rig.skeleton;
                if (!parent.empty())
                    anchor = anchorOn(parent, rig.join.parentAt);
            }
        }
        anchors[i] = anchor;
        rig.anchor = anchor;
        state[i] = Done;
    };
    for (std::size_t i = 0; i < n; ++i)
        resolve(i);
    return anchors;
}

LoadedDocument open(const deep_build::Params &p)
{
    const auto loaded = readFinbook(deep_build::file(p));
    if (!loaded)
        qWarning("%s", qPrintable(loaded.error().message));
    return loaded ? std::move(*loaded) : LoadedDocument{};
}

// open(p) on a thread with a 1 MiB stack.
LoadedDocument openOnSmallStack(const deep_build::Params &p)
{
    const QByteArray bytes = deep_build::file(p);
    LoadedDocument doc;
    QThread *thread = QThread::create([&] {
        auto loaded = readFinbook(bytes);
        if (loaded) {
            Document d; // and as a Document holding it resolves them again
            adoptLoadedDocument(d, *loaded);
            doc = std::move(*loaded);
        }
    });
    thread->setStackSize(1 << 20);
    thread->start();
    thread->wait();
    delete thread;
    return doc;
}

// The work of resolving a frame's joins (bones and tree nodes looked at).
std::int64_t joinWork(Frame frame)
{
    for (StrokeGroup &g : frame.groups)
        g.rig.skeleton.anchor = {};
    std::int64_t budget = std::numeric_limits<std::int64_t>::max();
    join_detail::resolveJoinsWithin(frame, budget);
    return std::numeric_limits<std::int64_t>::max() - budget;
}

double fastestOpen(const QByteArray &bytes, int runs)
{
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < runs; ++r) {
        QElapsedTimer clock;
        clock.start();
        const bool ok = bool(readFinbook(bytes));
        best = std::min(best, double(clock.nsecsElapsed()) / 1e9);
        if (!ok)
            return -1;
    }
    return best;
}

} // namespace

class TestDeepStructures : public QObject {
    Q_OBJECT
private slots:
    void longJoinChainsOpen_data();
    void longJoinChainsOpen();
    void joinTreeOpens();
    void longBoneChainOpensAndPoses();
    void anchorsAreThoseOfTheRecursiveResolution_data();
    void anchorsAreThoseOfTheRecursiveResolution();
    void manyPartsOnAHugeSkeletonCostNearlyLinear();
    void joinsTooCostlyToResolveAreRefused();
    void everyShapeGoesThroughTheFuzzChecks();
    void layersOpenUpToTheLimit();
};

void TestDeepStructures::longJoinChainsOpen_data()
{
    QTest::addColumn<bool>("reversed");
    QTest::newRow("each joined to the next") << false;
    QTest::newRow("each joined to the one before") << true;
}

// One frame of 80,000 objects, each a one-joint skeleton joined to the next: resolving the
// joins recursed 80,000 deep and the reader died of a stack overflow.
void TestDeepStructures::longJoinChainsOpen()
{
    QFETCH(bool, reversed);
    const int n = 80000;
    // On a thread with a small stack, so recursion per join fails here whatever the main
    // thread's stack limit (the recursion took about 100 bytes a join in a release build).
    const LoadedDocument doc = openOnSmallStack({Shape::JoinChain, n, 0, 7, true, reversed});
    QCOMPARE(doc.frames.size(), std::size_t(1));
    const Frame &f = doc.frames[0];
    QCOMPARE(int(f.groups.size()), n);
    // Everything hangs but the chain's top.
    const auto hanging = std::count_if(f.groups.begin(), f.groups.end(),
                                       [](const StrokeGroup &g) { return g.rig.skeleton.hangs(); });
    QCOMPARE(int(hanging), n - 1);
    const Id top = reversed ? f.groups.front().id : f.groups.back().id;
    const Id bottom = reversed ? f.groups.back().id : f.groups.front().id;
    QCOMPARE(characterRoot(f, bottom), top);
    QCOMPARE(int(characterParts(f, bottom).size()), n);
}

void TestDeepStructures::joinTreeOpens()
{
    const int n = 80000;
    const LoadedDocument doc = open({Shape::JoinTree, n, 0, 9, true, false});
    QCOMPARE(doc.frames.size(), std::size_t(1));
    const Frame &f = doc.frames[0];
    const auto hanging = std::count_if(f.groups.begin(), f.groups.end(),
                                       [](const StrokeGroup &g) { return g.rig.skeleton.hangs(); });
    QCOMPARE(int(hanging), n - 1);
    QCOMPARE(characterRoot(f, f.groups.back().id), f.groups.front().id);
}

// 100,000 joints in one chain: forward kinematics, the anchors of a part on it and an IK
// drag of its last joint stay bounded (the drag turns at most kMaxIkChainBones bones).
void TestDeepStructures::longBoneChainOpensAndPoses()
{
    const int n = 100000;
    const LoadedDocument doc = open({Shape::JointChain, n, 0, 11, true, false});
    QCOMPARE(doc.frames.size(), std::size_t(1));
    const SkeletonRig &rig = doc.frames[0].groups[0].rig.skeleton;
    QCOMPARE(rig.jointCount(), n);
    const std::vector<QPointF> posed = rig.posedJoints();
    QCOMPARE(int(posed.size()), n);
    QVERIFY(std::all_of(posed.begin(), posed.end(),
                        [](QPointF p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }));
    Eigen::MatrixX2d V(n, 2);
    Eigen::VectorXi P(n);
    for (int j = 0; j < n; ++j) {
        V.row(j) << rig.joints[std::size_t(j)].x(), rig.joints[std::size_t(j)].y();
        P(j) = rig.parent[std::size_t(j)];
    }
    // Re-rooting walks the whole tree (geometry::setRoot): at the far end of the chain.
    const auto rerooted = withRootJoint(rig.atRest(), n - 1);
    QVERIFY(rerooted);
    QCOMPARE(rerooted->jointCount(), n);
    QCOMPARE(rerooted->parent[std::size_t(rerooted->root)], -1);
    const auto skeleton = deform::makeSkeleton(V, P);
    QVERIFY(skeleton);
    const Eigen::VectorXi chain = deform::ikChain(*skeleton, n - 1, {});
    QCOMPARE(int(chain.size()), deform::kMaxIkChainBones);
    QElapsedTimer clock;
    clock.start();
    const auto solved = deform::solveIk(*skeleton, deform::restPose(*skeleton), n - 1,
                                        V.row(n - 1).transpose() + Eigen::Vector2d(-0.5, 0.3), {});
    qInfo("IK drag on a %d-joint chain: %.3f s", n, double(clock.nsecsElapsed()) / 1e9);
    QVERIFY(solved);
    QVERIFY(solved->pose.angles.allFinite());
    QVERIFY(int(solved->chain.size()) <= deform::kMaxIkChainBones);
}

void TestDeepStructures::anchorsAreThoseOfTheRecursiveResolution_data()
{
    QTest::addColumn<int>("seed");
    for (int seed = 1; seed <= 40; ++seed)
        QTest::newRow(qPrintable(QString::number(seed))) << seed;
}

// Random frames: parts joined to random others (loops, self-joins, missing parents, repeated
// ids) on skeletons of up to 300 joints, some piled on one spot (ties between bones): the
// iterative resolution and its bone index give exactly the anchors of the recursive scan.
void TestDeepStructures::anchorsAreThoseOfTheRecursiveResolution()
{
    QFETCH(int, seed);
    deep_build::detail::Random random(std::uint32_t(seed) * 7919u);
    Frame f;
    f.id = 1;
    const int n = 2 + int(random.next() % 60);
    for (int i = 0; i < n; ++i) {
        StrokeGroup g;
        g.id = 10 + Id(random.next() % 8 == 0 ? 0 : i); // some ids repeat
        const int joints = random.next() % 3 == 0 ? 1 + int(random.next() % 300) : 1;
        const bool piled = random.next() % 4 == 0;
        g.rig.skeleton =
            deep_build::detail::chainRig(joints, QPointF(random.unit() * 50, 0), piled ? 0.0 : 1.0,
                                         random, true, random.next() % 2 == 0);
        if (random.next() % 5 != 0) {
            const Id parent = 10 + Id(random.next() % std::uint32_t(n + 2));
            const QPointF at(random.unit() * 60 - 5, random.unit() * 20 - 10);
            g.rig.skeleton.join = SkeletonJoin{parent, at, at};
        }
        f.groups.push_back(std::move(g));
    }
    const std::vector<SkeletonAnchor> expected = referenceAnchors(f);
    Frame resolved = f;
    resolveJoins(resolved);
    for (int i = 0; i < n; ++i)
        QVERIFY2(resolved.groups[std::size_t(i)].rig.skeleton.anchor == expected[std::size_t(i)],
                 qPrintable(QStringLiteral("object %1").arg(i)));
}

// One skeleton of J joints with P parts joined to it: ten times the file (J and P) must cost
// about ten times as much, not a hundred (every part scanned every bone: 100,000 joints ×
// 10,000 parts was still opening after two minutes). Counted in bones and tree nodes looked
// at, which the machine's load does not disturb, and timed (fastest of several) for the record.
void TestDeepStructures::manyPartsOnAHugeSkeletonCostNearlyLinear()
{
    const deep_build::Params small{Shape::JoinStar, 10000, 1000, 13, true, false};
    deep_build::Params large = small;
    large.n *= 10;
    large.parts *= 10;
    const LoadedDocument a = open(small), b = open(large);
    QCOMPARE(int(b.frames.at(0).groups.size()), large.parts + 1);
    QVERIFY(std::all_of(b.frames[0].groups.begin() + 1, b.frames[0].groups.end(),
                        [](const StrokeGroup &g) { return g.rig.skeleton.hangs(); }));
    const std::int64_t workSmall = joinWork(a.frames[0]), workLarge = joinWork(b.frames[0]);
    const double smallSeconds = fastestOpen(deep_build::file(small), 3);
    const double largeSeconds = fastestOpen(deep_build::file(large), 3);
    qInfo("joins: work %lld -> %lld (x%.1f); open %.3f s -> %.3f s (x%.1f)", (long long)workSmall,
          (long long)workLarge, double(workLarge) / double(workSmall), smallSeconds, largeSeconds,
          largeSeconds / smallSeconds);
    QVERIFY2(workLarge <= 12 * workSmall, qPrintable(QString::number(workLarge)));
    QVERIFY(smallSeconds > 0 && largeSeconds > 0);
}

// Parts hanging at the centre of a star of 100,000 bones are equally near thousands of them:
// no index helps, and resolving would cost parts × joints. Such a file is refused as too
// costly, in one sentence; "open anyway" opens it with those parts standing alone.
void TestDeepStructures::joinsTooCostlyToResolveAreRefused()
{
    deep_build::Params p{Shape::JoinStar, 100000, 10000, 17, false, false};
    p.star = true;
    const QByteArray bytes = deep_build::file(p);
    QElapsedTimer clock;
    clock.start();
    const auto loaded = readFinbook(bytes);
    qInfo("refused in %.2f s", double(clock.nsecsElapsed()) / 1e9);
    QVERIFY(!loaded);
    QCOMPARE(loaded.error().code, FileErrorCode::TooLarge);
    QVERIFY2(loaded.error().message.contains(QLatin1String("too costly")),
             qPrintable(loaded.error().message));
    QStringList problems;
    const auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered);
    QCOMPARE(problems.size(), 1);
    QVERIFY(std::none_of(recovered->frames[0].groups.begin(), recovered->frames[0].groups.end(),
                         [](const StrokeGroup &g) { return g.rig.skeleton.join.joined(); }));
    // Fewer parts there resolve within the allowance.
    p.parts = 10;
    QVERIFY(readFinbook(deep_build::file(p)));
}

// What finbook-fuzz-deep does to each input, on every shape at a moderate size, as generated
// and with bytes flipped (checksums made right or not): keeps its code built and working in
// every preset, not only the fuzz one.
void TestDeepStructures::everyShapeGoesThroughTheFuzzChecks()
{
    for (int shape = 0; shape < int(Shape::Count); ++shape) {
        const int n = Shape(shape) == Shape::Layers ? kMaxLayers : 5000;
        deep_build::Params p{Shape(shape), n, 500, std::uint32_t(31 + shape), true, false};
        QByteArray bytes = deep_build::file(p);
        QVERIFY(readFinbook(bytes));
        fuzz_checks::readEveryWay(bytes);
        deep_build::detail::Random random(std::uint32_t(shape) + 1);
        for (int edit = 0; edit < 8; ++edit)
            bytes[qsizetype(random.next() % std::uint32_t(bytes.size()))] ^= char(1 << (edit % 8));
        fuzz_checks::readEveryWay(bytes);
        fuzz_checks::readEveryWay(fuzz_checks::withChecksums(bytes));
    }
}

// A file may hold 1,000 layers; one more is refused, or put on one layer when opened anyway.
// Properties past their limits are refused, or mended.
void TestDeepStructures::layersOpenUpToTheLimit()
{
    deep_build::Params p{Shape::Layers, kMaxLayers, 0, 5, false, false};
    const auto loaded = readFinbook(deep_build::file(p));
    QVERIFY(loaded);
    QCOMPARE(int(loaded->layers.size()), kMaxLayers);
    p.n = kMaxLayers + 1;
    const QByteArray tooMany = deep_build::file(p);
    QVERIFY(!readFinbook(tooMany));
    QStringList problems;
    auto mended = recoverFinbook(tooMany, &problems);
    QVERIFY(mended);
    QVERIFY(mended->layers.empty()); // one layer: every frame on it
    QVERIFY(!problems.isEmpty());
    p = {Shape::Layers, 300, 0, 6, false, false, true}; // wild properties
    const QByteArray wild = deep_build::file(p);
    QVERIFY(!readFinbook(wild));
    problems.clear();
    mended = recoverFinbook(wild, &problems);
    QVERIFY(mended);
    QCOMPARE(int(mended->layers.size()), 300);
    for (const LoadedLayer &l : mended->layers) {
        QVERIFY(l.properties.opacity >= 0.0 && l.properties.opacity <= 1.0);
        QVERIFY(l.properties.depth >= kMinLayerDepth && l.properties.depth <= kMaxLayerDepth);
    }
    QVERIFY(!problems.isEmpty());
}

QTEST_GUILESS_MAIN(TestDeepStructures)
#include "tst_deep_structures.moc"
