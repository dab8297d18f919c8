// Precompiled once for every ui and app test (tests/CMakeLists.txt): the headers most of them
// read. Parsing <QtTest> alone costs seconds per file; a test still includes what it uses.
#pragma once
#include "model.h"

#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QtWidgets>
