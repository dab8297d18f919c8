// Internal: Eigen ↔ Clipper conversion and shared checks. Clipper works on integers, so
// every operation runs in a frame translated to the input's corner and scaled to 1/256 px.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>

#include <Eigen/Core>
#include <polyclipping/clipper.hpp>

#include <exception>
#include <string>
#include <vector>

namespace finbook::geometry::detail {

inline constexpr double kUnitsPerPixel = 256.0;

struct ClipperFrame {
    Eigen::RowVector2d origin = Eigen::RowVector2d::Zero();

    ClipperLib::cInt units(double px) const;
    double pixels(double units) const { return units / kUnitsPerPixel; }
    ClipperLib::Path toPath(const Eigen::MatrixX2d &points) const;
    Eigen::MatrixX2d toRing(const ClipperLib::Path &path) const;
};

// Frame for points whose finite rows span [lo, hi] (already checked against kMaxCoordinate).
ClipperFrame frameFor(const Eigen::RowVector2d &lo);

// Every ring of the tree as a Region (islands inside holes become polygons of their own),
// outer rings positive, holes negative.
Region treeToRegion(const ClipperLib::PolyTree &tree, const ClipperFrame &frame);

// Union of closed paths into a tree of outer rings and holes. Not Clipper's StrictlySimple
// mode: it is quadratic (half the time on a 5,000-point outline), and the pinches it would
// remove are fine for the mesher (isSimple with Touching::AllowedAtPoints).
void uniteToTree(const ClipperLib::Paths &paths, ClipperLib::PolyFillType fill,
                 ClipperLib::PolyTree &tree);

// Round-joined offset of closed paths (delta < 0 erodes).
ClipperLib::Paths offsetClosed(const ClipperLib::Paths &paths, double deltaPx,
                               double arcTolerancePx, const ClipperFrame &frame);

// Douglas–Peucker on every ring; keeps the original rings where that breaks simplicity.
Region simplifyRegion(const Region &region, double tolerance);

// Counts finite points, checks them against kMaxCoordinate, and widens [lo, hi].
// `what` names the input in the message ("stroke 3", "ring 2").
Expected<long, GeometryError> checkPoints(const Eigen::MatrixX2d &points, const std::string &what,
                                          Eigen::RowVector2d &lo, Eigen::RowVector2d &hi);

GeometryError error(GeometryErrorCode code, std::string message);

// Clipper reports impossible input by throwing, and absurd input can exhaust memory; the
// geometry layer reports both as values. fn returns an Expected<…, GeometryError>.
template <class Fn> auto catchExceptions(Fn &&fn) -> decltype(fn())
{
    try {
        return fn();
    } catch (const std::exception &e) {
        return unexpected(error(GeometryErrorCode::ClippingFailed,
                                std::string("Combining the outlines failed: ") + e.what()));
    }
}

} // namespace finbook::geometry::detail
