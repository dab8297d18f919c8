// Stage two of the automatic skeleton: the raw skeleton → bones, under the four refinement
// controls of RealSkel (Ma et al. 2021). A pure function of (raw skeleton, options): sliders
// re-run it from the same raw skeleton, so any setting gives the same bones every time.
//
// Order: prune short terminal branches → merge junctions that are close → split every branch
// (junction–terminal, junction–junction, terminal–terminal) into bones by bounded
// Douglas–Peucker → collapse short internal bones → root the tree.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Core>

#include <limits>
#include <optional>

namespace finbook::geometry {

struct RefineOptions {
    // Bone complexity: the Douglas–Peucker tolerance (px) of each branch. A branch is also cut
    // wherever a straight bone would stray further than half the local inscribed radius from
    // the skeleton, so bones stay inside the shape whatever the tolerance; +inf gives the
    // fewest such bones, 0 a bone per raw skeleton edge. ≥ 0.
    double boneTolerance = std::numeric_limits<double>::infinity();
    // Junctions joined by a branch shorter than this (px) become one junction: the one with
    // the largest inscribed disk. ≥ 0; 0 merges nothing.
    double mergeDistance = 0.0;
    // Terminal branches (tip to junction) shorter than this (px) are removed, shortest first.
    // ≥ 0; a part always keeps at least one branch.
    double pruneLength = 0.0;
    // Bones between two non-terminal joints shorter than this (px) collapse into one joint,
    // shortest first, unless that would take a neighbouring bone outside the shape. ≥ 0.
    double collapseLength = 0.0;
    // The character root: the joint nearest this point (canvas px). Default: with animatorRig
    // the joint with the largest inscribed disk (the body's thickest part; inner joints before
    // tips), else the joint nearest the region's centre of mass.
    std::optional<Eigen::Vector2d> rootNear;
    // A rig an animator accepts as it comes (issue 21), on top of the four px controls above:
    //  - clean-up relative to the local width: side branches shorter than 1.1 junction radii,
    //    or shorter than 2 and not ending in a limb's tip (the outline turns less than 135°
    //    there: a box corner turns 90°, a stubby finger 180°) go; junctions inside each
    //    other's inscribed disk merge; inner bones shorter than half the width at their ends
    //    collapse, and so do stubs at tips;
    //  - a base joint where each limb leaves the body (the width drops from the junction's to
    //    the limb's) and, on a limb longer than 6 of its radii, a middle joint where it bends
    //    most, else narrows, else half way;
    //  - the root at the thickest part, and separate pieces (polygons) hung from the nearest
    //    bone of the root's tree (split there when the point lies inside the bone): the only
    //    bones that may leave the shape.
    // false: RealSkel's pipeline alone, with a tree per polygon rooted near its centre of mass.
    bool animatorRig = true;
};

// Slider ranges for a raw skeleton, in px (after RealSkel's dialogs): bone tolerance up to
// the largest inscribed radius, merge up to the longest junction–junction branch, prune up
// to the longest terminal branch, collapse up to the longest branch. Every maximum is > 0.
struct RefineRanges {
    double boneTolerance = 1.0;
    double mergeDistance = 1.0;
    double pruneLength = 1.0;
    double collapseLength = 1.0;
};
RefineRanges refineRanges(const RawSkeleton &raw);

// Errors: InvalidOptions (a negative or NaN length). Promise: isValidSkeleton, part = 0 for
// every joint, J ≥ 1 (J == 0 only when raw has no nodes), every bone inside raw.contour (but those
// that join separate pieces).
Expected<Skeleton, GeometryError> refineSkeleton(const RawSkeleton &raw,
                                                 const RefineOptions &options = {});

// rawSkeleton + refineSkeleton: the whole pipeline from an object's silhouette.
Expected<Skeleton, GeometryError> skeletonize(const Region &region,
                                              const SkeletonOptions &skeletonOptions = {},
                                              const RefineOptions &refineOptions = {});

} // namespace finbook::geometry
