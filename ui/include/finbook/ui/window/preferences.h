// The editor's preferences: what new documents start with, and the onion skin (the current
// one: the main window saves it whenever it changes, so it comes back at the next start).
// Stored in QSettings under "preferences/".
#pragma once

#include <finbook/ui/window/editor_state.h>

#include <QSize>

class QSettings;

namespace finbook::ui {

struct Preferences {
    OnionSkin onionSkin;
    int frameRate = 12;          // frames per second of new documents
    QSize canvasSize{1280, 720}; // page size of new documents
    int autosaveMinutes = 2;     // a recovery copy of unsaved changes this often; 0 = never

    static Preferences load(QSettings &settings);
    void save(QSettings &settings) const;
    friend bool operator==(const Preferences &, const Preferences &) = default;
};

} // namespace finbook::ui
