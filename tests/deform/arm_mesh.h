// The deform tests' bent-arm fixture: a 300 × 40 bar along x with an elbow joint at x = 150
// (bones 0→1 and 1→2), inscribed radius 20 everywhere.
#pragma once

#include "grid_mesh.h"

#include <finbook/deform/skeleton/skeleton.h>

#include <Eigen/Core>

namespace finbook::test {

struct Arm {
    GridMesh mesh = gridMesh(60, 8, 300.0, 40.0, 0.1);
    deform::Skeleton skeleton;
    Eigen::VectorXd radius = Eigen::Vector3d(20.0, 20.0, 20.0);
    Arm()
    {
        Eigen::MatrixX2d joints(3, 2);
        joints << 0.0, 20.0, 150.0, 20.0, 300.0, 20.0;
        skeleton = *deform::makeSkeleton(joints, Eigen::Vector3i(-1, 0, 1));
    }
    double elbowDistance(Eigen::Index v) const
    {
        return (mesh.V.row(v) - skeleton.joints.row(1)).norm();
    }
};

} // namespace finbook::test
