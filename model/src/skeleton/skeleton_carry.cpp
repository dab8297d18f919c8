#include <finbook/model/skeleton/skeleton_carry.h>

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace finbook::model {

namespace {

constexpr double kReach = 1.5; // inscribed radii

// 1 for a tip, 2 for an inner joint, 3 for a junction (0: a lone joint).
std::vector<int> kinds(const SkeletonRig &rig)
{
    std::vector<int> degree(rig.joints.size(), 0);
    for (std::size_t j = 0; j < rig.parent.size(); ++j) {
        if (rig.parent[j] >= 0) {
            ++degree[j];
            ++degree[std::size_t(rig.parent[j])];
        }
    }
    for (int &d : degree)
        d = std::min(d, 3);
    return degree;
}

// The joint of `in` of kind `kind` nearest p, −1 if none.
int nearest(const SkeletonRig &in, const std::vector<int> &kind, int wanted, QPointF p)
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < in.joints.size(); ++j) {
        const double d = QLineF(in.joints[j], p).length();
        if (kind[j] == wanted && d < bestDistance) {
            bestDistance = d;
            best = int(j);
        }
    }
    return best;
}

} // namespace

SkeletonRig carryHandEdits(const SkeletonRig &old, const SkeletonRig &rebuilt)
{
    if (!old.isValid() || !rebuilt.isValid() || old.empty() || rebuilt.empty())
        return rebuilt;
    const std::vector<int> oldKind = kinds(old), newKind = kinds(rebuilt);
    SkeletonRig out = rebuilt;
    std::vector<bool> locked(out.joints.size(), false);
    for (std::size_t j = 0; j < rebuilt.joints.size(); ++j) {
        const int i = nearest(old, oldKind, newKind[j], rebuilt.joints[j]);
        if (i < 0 || nearest(rebuilt, newKind, oldKind[std::size_t(i)],
                             old.joints[std::size_t(i)]) != int(j))
            continue;
        const double reach = kReach * std::max(old.radius[std::size_t(i)], rebuilt.radius[j]);
        if (QLineF(old.joints[std::size_t(i)], rebuilt.joints[j]).length() > reach)
            continue;
        out.joints[j] = old.joints[std::size_t(i)];
        locked[j] = old.isLocked(i);
    }
    out.locked.clear();
    if (std::any_of(locked.begin(), locked.end(), [](bool l) { return l; }))
        out.locked = locked;
    return out.isValid() ? out : rebuilt;
}

} // namespace finbook::model
