// Precompiled once for every geometry test (tests/CMakeLists.txt): the headers most of them
// read. Parsing <QtTest> alone costs seconds per file; a test still includes what it uses.
#pragma once
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QtTest>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
