// Help → Keyboard Shortcuts: every action with its current shortcut, plus the canvas gestures
// that are not actions (Space-drag, middle-drag, wheel).
#pragma once

#include <QDialog>

namespace finbook::ui {

class ShortcutRegistry;

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ShortcutsDialog(const ShortcutRegistry *registry, QWidget *parent = nullptr);
    int rowCount() const { return m_rows; }

private:
    int m_rows = 0;
};

} // namespace finbook::ui
