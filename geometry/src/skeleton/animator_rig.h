// Internal: the steps that make the automatic skeleton a rig an animator accepts as it comes
// (issue 21): clean-up relative to the local width (junction clusters, corner spurs, tiny
// branches), joints where limbs leave the body and bend, the root at the thickest part, and
// separate pieces of one object hung from the nearest bone.
#pragma once

#include "bone_graph.h"
#include "dense_graph.h"
#include "skeleton_tree.h"

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::detail {

// A side branch shorter than this many junction radii is a spur unless the outline turns like
// a limb's tip at its end; one that stays within kInsideDisk junction radii (tip disk
// included) always is.
inline constexpr double kSpurLength = 2.0;
inline constexpr double kInsideDisk = 1.3;
// The outline turns at least this much (radians) around a limb's tip: a finger's cap turns π,
// a pointed ear about 2π/3; a box corner turns π/2.
inline constexpr double kTipTurning = 0.65 * 3.14159265358979323846;

// Turning (radians) of the outline of `contour` within `reach` of p: π for the cap of a
// finger whose centre is p, π/2 at a box corner. Reflex corners count against convex ones
// within half the reach (a pen's round cap standing out of a corner, at the foot of a trunk
// drawn open, turns out and back in: still a corner), not further off (where a stubby limb
// leaves the body).
double outlineTurning(const Polygon &contour, const Eigen::Vector2d &p, double reach);

// Clean-up by default, relative to the inscribed radius: side branches that stay inside their
// junction's disk, or are corner spurs (short, and the outline turns less than kTipTurning
// around their tip), or, long, run side by side with a longer branch to a tip and inside its
// width (kInsideDisk of it all along), go, shortest first.
void removeCornerSpurs(DenseGraph &graph, const Region &contour);

// Whether the branch a–…–z joining two junctions is a cluster to merge: shorter than the
// larger inscribed radius of its ends.
bool isJunctionCluster(const DenseGraph &graph, const Branch &branch);

// Positions along a branch (indices into branch.nodes) that must become joints: on a branch
// from a junction to a tip, the base where the width drops from the body's to the limb's
// (none when it does not drop: the junction is the base), and, on a long limb, a middle joint
// where it bends most or narrows (else half way). `bases` (if given) gets the positions among
// them that are limbs' bases. With the `contour` the skeleton was made from, a base where the
// limb is still one with the body on one side (that side's outline far off) moves out along
// the limb to where the outline comes in on both sides.
std::vector<int> limbJoints(const DenseGraph &graph, const Branch &branch,
                            std::vector<int> *bases = nullptr, const Region *contour = nullptr);

// Terminal bones shorter than half the inscribed radius at their inner end go (the tip moves
// in to that joint), as long as that joint is an inner one and the bone that then reaches
// the tip stays inside: a stub at a limb's end.
void trimTinyTips(DenseGraph &bones, const Contours &contours);

// The joint with the largest inscribed radius among those of `polygon` (any polygon if −1),
// or an inner joint at least 90 % as thick: where the body is thickest.
int thickestJoint(const JointGraph &graph, const std::vector<int> &polygonOf, int polygon);

// Splits skeleton edges longer than the width at their ends into pieces about that long
// (radius and clearance interpolated; exact along a straight-skeleton edge), so a straight
// limb has places along it where limbJoints can put a joint.
void subdivideLongEdges(DenseGraph &graph);

// Joins the trees of the forest to the tree of `root`, nearest first (the tree with the joint
// nearest to an attached bone). Only pieces that touch or nearly touch are joined (issue 48): a
// piece whose polygon of `contour` lies further from the attached pieces' polygons than the
// thicker of the two pieces' widest radius keeps a tree of its own, and the pieces near it hang
// from it (a second bird, the letters of a word are not hung across open air). A joined tree
// hangs where the outlines come closest: by its joint nearest that contact, from the bone of
// the attached piece nearest the contact on its side (split there by a new joint when the
// point lies inside it, else from its nearer end); without polygons to say, by its joint
// nearest to an attached bone, from that bone. polygonOf grows with the new joints.
void joinPieces(JointGraph &graph, std::vector<int> &polygonOf, int root, const Region &contour);

} // namespace finbook::geometry::detail
