// Edit → Preferences: new-document defaults, the onion skin and keyboard shortcuts (two per
// command: a shortcut and an alternative).
// The dialog refuses to close with OK while two actions share a shortcut.
#pragma once

#include <finbook/ui/window/preferences.h>

#include <QDialog>
#include <QKeySequence>
#include <QMap>

class QSpinBox;

namespace finbook::ui {

class OnionSkinEditor;
class ShortcutEditor;
class ShortcutRegistry;

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    PreferencesDialog(const Preferences &preferences, const ShortcutRegistry *shortcuts,
                      QWidget *parent = nullptr);

    Preferences preferences() const;
    QMap<QString, QList<QKeySequence>> shortcuts() const;
    ShortcutEditor *shortcutEditor() const { return m_shortcuts; }

    void accept() override;

private:
    QWidget *createGeneralPage(const Preferences &preferences);

    QSpinBox *m_fps = nullptr;
    QSpinBox *m_width = nullptr;
    QSpinBox *m_height = nullptr;
    QSpinBox *m_autosave = nullptr;
    OnionSkinEditor *m_onion;
    ShortcutEditor *m_shortcuts;
};

} // namespace finbook::ui
