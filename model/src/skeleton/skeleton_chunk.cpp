// Reading an object's "SKEL" chunk (the layout is in finbook_file_format.h). Everything is
// checked before the skeleton reaches the document: counts against the bytes left, finite
// numbers, parents before children, a root that is a root, settings in [0, 1], a known mode,
// lock flags 0 or 1.
#include "../finbook_file_reader.h"

#include <algorithm>
#include <cmath>

namespace finbook::model::file_format {

namespace {
double finiteF64(Cursor &c, const char *what, const QString &problem)
{
    const double v = c.f64(what);
    if (!std::isfinite(v))
        c.fail(FileErrorCode::BadValue, problem);
    return v;
}
} // namespace

SkeletonRig Reader::readSkeleton(Cursor &c)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the skeleton");
    const quint32 n = c.count(kJointBytes, what);
    if (n == 0)
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("its skeleton has no joints"));
    SkeletonRig s;
    s.joints.resize(n);
    s.radius.resize(n);
    s.parent.resize(n);
    s.angles.resize(n);
    for (quint32 j = 0; j < n; ++j) {
        const QString bad = FinbookFile::tr("skeleton joint %1 has a non-finite value").arg(j + 1);
        const double x = finiteF64(c, what, bad);
        const double y = finiteF64(c, what, bad);
        s.joints[j] = QPointF(x, y);
        s.radius[j] = finiteF64(c, what, bad);
        if (s.radius[j] < 0.0)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("skeleton joint %1 has a negative radius").arg(j + 1));
        s.parent[j] = c.i32(what);
        if (s.parent[j] < -1 || s.parent[j] >= qint64(j))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("skeleton joint %1 has an invalid parent").arg(j + 1));
        s.angles[j] = finiteF64(c, what, bad);
    }
    s.root = c.i32(what);
    if (s.root < 0 || quint32(s.root) >= n || s.parent[std::size_t(s.root)] != -1)
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the skeleton's root is not a root joint"));
    const QString badPose = FinbookFile::tr("the skeleton's pose has a non-finite value");
    const double ox = finiteF64(c, what, badPose);
    s.rootOffset = QPointF(ox, finiteF64(c, what, badPose));
    const QString badSettings = FinbookFile::tr("a skeleton setting is outside 0 to 1");
    for (double *v :
         {&s.settings.complexity, &s.settings.merge, &s.settings.prune, &s.settings.collapse}) {
        *v = finiteF64(c, what, badSettings);
        if (*v < 0.0 || *v > 1.0)
            c.fail(FileErrorCode::BadValue, badSettings);
    }
    const quint8 mode = c.u8(what);
    if (mode > quint8(kLastSkinningMode))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the skeleton has an unknown skinning mode"));
    s.mode = SkinningMode(mode);
    // Joint locks came later as an optional tail: a chunk that ends here has none.
    if (!c.atEnd()) {
        const char *locks = c.take(n, what);
        s.locked.resize(n);
        for (quint32 j = 0; j < n; ++j) {
            if (quint8(locks[j]) > 1)
                c.fail(FileErrorCode::BadValue,
                       FinbookFile::tr("skeleton joint %1 has an unknown lock state").arg(j + 1));
            s.locked[j] = locks[j] != 0;
        }
        if (std::none_of(s.locked.begin(), s.locked.end(), [](bool l) { return l; }))
            s.locked.clear();
    }
    return s;
}

void Reader::readLimbBasesChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the skeleton's limb bases");
    SkeletonRig &s = g.rig.skeleton;
    if (s.empty())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("limb bases come without a skeleton"));
    const quint32 n = c.count(1, what);
    if (n != s.joints.size())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the skeleton has %1 joints but %2 limb "
                                                        "base flags")
                                            .arg(s.joints.size())
                                            .arg(n));
    const char *flags = c.take(n, what);
    std::vector<bool> bases(n);
    for (quint32 j = 0; j < n; ++j) {
        if (quint8(flags[j]) > 1)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("skeleton joint %1 has an unknown limb base flag").arg(j + 1));
        bases[j] = flags[j] != 0;
    }
    if (std::any_of(bases.begin(), bases.end(), [](bool b) { return b; }))
        s.limbBase = std::move(bases);
}

} // namespace finbook::model::file_format
