// The Shading panel (issue 27): how the current object's fills are shaded (flat, cel in two or
// three tones, smooth; rim light), and where the document's one light comes from. Each change
// is one undo step; the panel follows undo, the current object and the frame.
#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace finbook::ui {

class EditorState;

class ShadingPanel : public QWidget {
    Q_OBJECT
public:
    explicit ShadingPanel(EditorState *state, QWidget *parent = nullptr);

private:
    void sync();
    void shadingEdited();
    void lightEdited();

    EditorState *m_state;
    QComboBox *m_ramp = nullptr;
    QCheckBox *m_rim = nullptr;
    QLabel *m_hint = nullptr;
    QSpinBox *m_azimuth = nullptr;
    QSpinBox *m_elevation = nullptr;
};

} // namespace finbook::ui
