// Precompiled once for the benchmarks' files (tests/CMakeLists.txt): the headers most of them
// read. A file still includes what it uses.
#pragma once
#include <finbook/deform/arap.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/ui/window/editor_state.h>

#include <QtWidgets>

#include <algorithm>
#include <cmath>
#include <vector>
