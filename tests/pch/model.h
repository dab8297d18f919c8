// Precompiled once for every model test (tests/CMakeLists.txt): the headers most of them read.
// Parsing <QtTest> alone costs seconds per file; a test still includes what it uses.
#pragma once
#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>
