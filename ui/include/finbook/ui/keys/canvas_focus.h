// CanvasFocus: keeps the keyboard on the canvas, as in Krita and Pencil2D, so single-key
// shortcuts (B E V H P O M , .) keep working after the user touches a toolbar or panel.
//
// Watches the application's events for one main window (never its dialogs or menus):
//  - Return, Enter and Escape in a text or number field go to the field, not to a shortcut
//    (Return plays the animation on the canvas): Return confirms the field, Escape puts back
//    the value a spin box had when it got focus; either way the canvas then gets the focus.
//  - After a click, a wheel turn or a closed pop-up on any other control (spin box arrows, a
//    list row, a button), the canvas gets the focus back. A field keeps it only while it is
//    being edited: after a click into its text, while typing, or while a list's rename
//    editor is open.
// Keyboard navigation (Tab) is left alone.
#pragma once

#include <QObject>
#include <QPointer>
#include <QVariant>

class QAbstractSpinBox;
class QKeyEvent;

namespace finbook::ui {

class CanvasFocus : public QObject {
    Q_OBJECT
public:
    // Installs itself as an application event filter until destroyed. `canvas` is a
    // descendant of `window`; both must outlive this object or be its ancestors.
    CanvasFocus(QWidget *window, QWidget *canvas);
    ~CanvasFocus() override;

    // Widgets that take typed text: line edits, spin boxes, text edits, editable combo boxes
    // and key-sequence edits (or a part of one, e.g. a spin box's line edit).
    static QWidget *textFieldOf(QWidget *widget);
    // Confirm or cancel keys a field must receive: Return, Enter, Escape (no Ctrl/Alt/Meta).
    static bool isConfirmOrCancel(const QKeyEvent &event);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    bool belongsToWindow(const QWidget *widget) const;
    void keyEvent(QWidget *widget, QKeyEvent *event);
    void pointerEvent(QWidget *widget, QEvent *event);
    void focusIn(QWidget *widget, Qt::FocusReason reason);
    // Gives the canvas the focus after `hops` turns of the event loop, unless a field is
    // being edited or a dialog or pop-up has the keyboard by then.
    void returnFocusSoon(int hops);
    void hop();
    void returnFocus();
    bool isBeingEdited(QWidget *focus) const;

    QPointer<QWidget> m_window;
    QPointer<QWidget> m_canvas;
    QPointer<QWidget> m_editing;       // the field the user clicked into or typed in
    QPointer<QAbstractSpinBox> m_spin; // the spin box that has the focus
    QVariant m_spinValue;              // its value when it got the focus
    bool m_pending = false;            // a hop() is queued
    int m_hopsLeft = 0;
};

} // namespace finbook::ui
