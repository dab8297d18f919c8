// SwapPicker: under the objects panel's list, which drawing of its set the current object shows
// in this frame (issue 49), as a combo box; picking one is one undo step. Hidden when the
// current object is not swappable.
#pragma once

#include <finbook/model/types.h>

#include <QWidget>

class QComboBox;
class QLabel;

namespace finbook::ui {

class EditorState;
class SwapActions;

class SwapPicker : public QWidget {
    Q_OBJECT
public:
    SwapPicker(EditorState *state, SwapActions *actions, QWidget *parent = nullptr);
    QComboBox *combo() const { return m_combo; }

private:
    void refresh();
    void picked(int index);

    EditorState *m_state;
    SwapActions *m_actions;
    QLabel *m_label;
    QComboBox *m_combo;
    bool m_refreshing = false;
};

} // namespace finbook::ui
