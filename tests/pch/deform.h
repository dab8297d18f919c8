// Precompiled once for every deform test (tests/CMakeLists.txt): the headers most of them
// read. Parsing <QtTest> alone costs seconds per file; a test still includes what it uses.
#pragma once
#include <finbook/deform/arap.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/object_mesh.h>

#include <QtTest>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>
