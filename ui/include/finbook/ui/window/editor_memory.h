// What the editor remembers between runs without being asked: the pen (colour, width,
// smoothing) and the current tool. The onion skin is remembered with the preferences
// (Preferences::onionSkin). Stored in QSettings under "editor/".
#pragma once

#include <finbook/ui/tools/tool_pen.h>

#include <QString>

class QSettings;

namespace finbook::ui {

struct EditorMemory {
    PenSettings pen;
    QString tool; // a tool id such as "tool.pen"; empty: the window's first tool

    // Missing or unusable values (an invalid colour, a width out of range) read as defaults.
    static EditorMemory load(QSettings &settings);
    void save(QSettings &settings) const;
    friend bool operator==(const EditorMemory &, const EditorMemory &) = default;
};

} // namespace finbook::ui
