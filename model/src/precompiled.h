// Precompiled once for the model library's files (model/CMakeLists.txt): the headers most of
// them read, so that each file does not parse Qt and the lower layers again. A file still
// includes what it uses.
#pragma once
#include <finbook/model/document.h>
#include <finbook/model/render.h>

#include <QtGui>

#include <algorithm>
#include <cmath>
#include <vector>
