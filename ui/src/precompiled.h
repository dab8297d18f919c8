// Precompiled once for the ui library's files (ui/CMakeLists.txt): the headers most of them
// read, so that each file does not parse Qt and the lower layers again. A file still includes
// what it uses.
#pragma once
#include <finbook/model/document.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QtWidgets>

#include <algorithm>
#include <cmath>
#include <vector>
