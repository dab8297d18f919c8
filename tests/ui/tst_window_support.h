// Helpers for tests that drive the whole main window the way a person does: keys go to
// whichever widget has the keyboard focus, clicks land on the widget under the pointer.
#pragma once

#include "tst_tools_support.h"

#include <finbook/ui/window/main_window.h>

#include <QAbstractSpinBox>
#include <QLineEdit>
#include <QStyle>
#include <QStyleOptionSpinBox>

namespace finbook::test {

// A key press where the window system would send it: to the focus widget.
inline void typeKey(Qt::Key key, Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    QTest::keyClick(static_cast<QWidget *>(nullptr), key, mods);
}

inline void typeText(const QString &text)
{
    QTest::keyClicks(static_cast<QWidget *>(nullptr), text);
}

// The centre of a spin box's up or down arrow, in its own coordinates.
inline QPoint spinArrow(const QAbstractSpinBox *spin, bool up)
{
    QStyleOptionSpinBox option;
    option.initFrom(spin);
    option.rect = spin->rect();
    option.subControls = QStyle::SC_All;
    option.buttonSymbols = spin->buttonSymbols();
    option.frame = spin->hasFrame();
    option.stepEnabled = QAbstractSpinBox::StepUpEnabled | QAbstractSpinBox::StepDownEnabled;
    return spin->style()
        ->subControlRect(QStyle::CC_SpinBox, &option,
                         up ? QStyle::SC_SpinBoxUp : QStyle::SC_SpinBoxDown, spin)
        .center();
}

inline void clickSpinArrow(QAbstractSpinBox *spin, bool up = true)
{
    QTest::mouseClick(spin, Qt::LeftButton, {}, spinArrow(spin, up));
}

// A click into a field's text (for a spin box, its line edit), then Ctrl+A to select it all.
inline void clickIntoText(QWidget *field)
{
    auto *edit = qobject_cast<QLineEdit *>(field);
    if (!edit)
        edit = field->findChild<QLineEdit *>();
    QTest::mouseClick(edit, Qt::LeftButton, {}, edit->rect().center());
    typeKey(Qt::Key_A, Qt::ControlModifier);
}

// Shows `window` at `size` and waits until it has the keyboard.
inline bool showActive(ui::MainWindow &window, QSize size = QSize(1280, 800))
{
    window.resize(size);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

} // namespace finbook::test
