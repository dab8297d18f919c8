// Snapping a pin to the mesh: called on click, so a linear scan is fine.
#pragma once

#include <Eigen/Core>

namespace finbook::deform {

// V  n×2. Returns the index of the row of V closest to p (lowest index on ties; non-finite
// rows are skipped), or −1 when V has no finite row.
int nearestVertex(const Eigen::MatrixX2d &V, const Eigen::Vector2d &p);

} // namespace finbook::deform
