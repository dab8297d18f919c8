// The editor's preferences: what new documents start with and the onion-skin defaults.
// Stored in QSettings under "preferences/".
#pragma once

#include <finbook/ui/editor_state.h>

#include <QSize>

class QSettings;

namespace finbook::ui {

struct Preferences {
    OnionSkin onionSkin;
    int frameRate = 12;          // frames per second of new documents
    QSize canvasSize{1280, 720}; // page size of new documents

    static Preferences load(QSettings &settings);
    void save(QSettings &settings) const;
    friend bool operator==(const Preferences &, const Preferences &) = default;
};

} // namespace finbook::ui
