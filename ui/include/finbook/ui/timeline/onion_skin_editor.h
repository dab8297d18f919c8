// Controls for OnionSkin settings (frames before/after, opacity, tints), used by the View
// menu's onion-skin dialog and by the preferences.
#pragma once

#include <finbook/ui/window/editor_state.h>

#include <QWidget>

class QCheckBox;
class QSpinBox;

namespace finbook::ui {

class ColorButton;

class OnionSkinEditor : public QWidget {
    Q_OBJECT
public:
    explicit OnionSkinEditor(QWidget *parent = nullptr);

    OnionSkin onionSkin() const;
    void setOnionSkin(const OnionSkin &onion);

signals:
    void onionSkinEdited(const finbook::ui::OnionSkin &onion);

private:
    QCheckBox *m_enabled;
    QSpinBox *m_before;
    QSpinBox *m_after;
    QSpinBox *m_opacity; // percent
    ColorButton *m_beforeTint;
    ColorButton *m_afterTint;
};

} // namespace finbook::ui
