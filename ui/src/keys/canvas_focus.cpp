#include <finbook/ui/keys/canvas_focus.h>

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFocusEvent>
#include <QKeyEvent>
#include <QKeySequenceEdit>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QToolBar>

#include <algorithm>

namespace finbook::ui {

namespace {
bool isTextEdit(const QWidget *widget)
{
    return qobject_cast<const QTextEdit *>(widget) || qobject_cast<const QPlainTextEdit *>(widget);
}

// Where typing happens: a line edit (alone or inside a spin box) or a text edit's viewport.
bool isTypingArea(const QWidget *widget)
{
    if (qobject_cast<const QLineEdit *>(widget))
        return true;
    const auto *area = qobject_cast<const QAbstractScrollArea *>(widget->parentWidget());
    return area && isTextEdit(area) && area->viewport() == widget;
}
} // namespace

CanvasFocus::CanvasFocus(QWidget *window, QWidget *canvas)
    : QObject(window)
    , m_window(window)
    , m_canvas(canvas)
{
    setObjectName(QStringLiteral("canvasFocus"));
    qApp->installEventFilter(this);
}

CanvasFocus::~CanvasFocus()
{
    qApp->removeEventFilter(this);
}

QWidget *CanvasFocus::textFieldOf(QWidget *widget)
{
    if (!widget)
        return nullptr;
    QWidget *parent = widget->parentWidget();
    // Composite fields own their line edit: the spin box is the field, not its text part.
    for (QWidget *w : {widget, parent}) {
        if (!w)
            continue;
        if (qobject_cast<QAbstractSpinBox *>(w) || qobject_cast<QKeySequenceEdit *>(w))
            return w;
        if (auto *combo = qobject_cast<QComboBox *>(w))
            return combo->isEditable() ? combo : nullptr;
    }
    if (qobject_cast<QLineEdit *>(widget) || isTextEdit(widget))
        return widget;
    if (parent && isTextEdit(parent) && isTypingArea(widget))
        return parent;
    return nullptr;
}

bool CanvasFocus::isConfirmOrCancel(const QKeyEvent &event)
{
    const int key = event.key();
    if (key != Qt::Key_Return && key != Qt::Key_Enter && key != Qt::Key_Escape)
        return false;
    return (event.modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier)) == Qt::NoModifier;
}

bool CanvasFocus::belongsToWindow(const QWidget *widget) const
{
    // Floating docks and toolbars are windows of their own but still part of the editor;
    // dialogs and menus are not.
    for (const QWidget *p = widget; p; p = p->parentWidget()) {
        if (p == m_window)
            return true;
        if (p->isWindow() && !qobject_cast<const QDockWidget *>(p) &&
            !qobject_cast<const QToolBar *>(p))
            return false;
    }
    return false;
}

bool CanvasFocus::eventFilter(QObject *watched, QEvent *event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::ShortcutOverride && type != QEvent::KeyPress &&
        type != QEvent::MouseButtonPress && type != QEvent::MouseButtonRelease &&
        type != QEvent::Wheel && type != QEvent::FocusIn && type != QEvent::FocusOut)
        return false;
    auto *widget = qobject_cast<QWidget *>(watched);
    if (!widget || !m_canvas || widget == m_canvas || m_canvas->isAncestorOf(widget) ||
        !belongsToWindow(widget))
        return false;
    switch (type) {
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress:
        keyEvent(widget, static_cast<QKeyEvent *>(event));
        break;
    case QEvent::MouseButtonPress:
        // A press into text (a context menu may open before any release): typing follows.
        if (QWidget *field = textFieldOf(widget); field && isTypingArea(widget))
            m_editing = field;
        break;
    case QEvent::MouseButtonRelease:
    case QEvent::Wheel:
        pointerEvent(widget, event);
        break;
    case QEvent::FocusIn:
        focusIn(widget, static_cast<QFocusEvent *>(event)->reason());
        break;
    case QEvent::FocusOut: {
        const Qt::FocusReason reason = static_cast<QFocusEvent *>(event)->reason();
        // A context menu or another window taking over for a moment does not end an edit.
        if (widget == m_editing && reason != Qt::PopupFocusReason &&
            reason != Qt::ActiveWindowFocusReason)
            m_editing = nullptr;
        break;
    }
    default:
        break;
    }
    return false; // only watches: every event still reaches its widget
}

void CanvasFocus::keyEvent(QWidget *widget, QKeyEvent *event)
{
    QWidget *field = textFieldOf(widget);
    if (!field)
        return;
    if (!isConfirmOrCancel(*event)) {
        if (event->type() == QEvent::KeyPress)
            m_editing = field; // typing: the field keeps the focus
        return;
    }
    if (event->type() == QEvent::ShortcutOverride) {
        // Accepting the override sends the key to the field instead of to a window
        // shortcut (Return would start playback).
        event->accept();
        return;
    }
    if (event->key() == Qt::Key_Escape && field == m_spin && m_spinValue.isValid())
        m_spin->setProperty("value", m_spinValue);
    m_editing = nullptr;
    // Two turns of the event loop: a list's rename editor commits and closes on the next
    // one, and the focus goes back to the canvas only after that.
    returnFocusSoon(2);
}

void CanvasFocus::pointerEvent(QWidget *widget, QEvent *event)
{
    if (event->type() == QEvent::MouseButtonRelease) {
        if (QWidget *field = textFieldOf(widget)) {
            if (isTypingArea(widget)) {
                m_editing = field; // a click into the text: the user is about to type
                return;
            }
            if (m_editing == field)
                m_editing = nullptr; // a spin box's arrows: a step, not typing
        }
    }
    returnFocusSoon(1);
}

void CanvasFocus::focusIn(QWidget *widget, Qt::FocusReason reason)
{
    QWidget *field = textFieldOf(widget);
    // Back from a context menu or another window, the edit goes on: keep what Escape restores.
    const bool resumed = reason == Qt::PopupFocusReason || reason == Qt::ActiveWindowFocusReason;
    if (!resumed || field != m_spin) {
        m_spin = qobject_cast<QAbstractSpinBox *>(field);
        m_spinValue = m_spin ? m_spin->property("value") : QVariant(); // what Escape puts back
    }
    switch (reason) {
    case Qt::TabFocusReason:
    case Qt::BacktabFocusReason:
    case Qt::ShortcutFocusReason:
        // Reached from the keyboard (Tab, a label's Alt+letter): the user means to type.
        if (field)
            m_editing = field;
        break;
    case Qt::PopupFocusReason:
        returnFocusSoon(1); // a combo box's list or a context menu closed
        break;
    default:
        break;
    }
}

void CanvasFocus::returnFocusSoon(int hops)
{
    m_hopsLeft = std::max(m_hopsLeft, hops);
    if (m_pending)
        return;
    m_pending = true;
    QMetaObject::invokeMethod(this, &CanvasFocus::hop, Qt::QueuedConnection);
}

void CanvasFocus::hop()
{
    if (--m_hopsLeft > 0) {
        QMetaObject::invokeMethod(this, &CanvasFocus::hop, Qt::QueuedConnection);
        return;
    }
    m_pending = false;
    returnFocus();
}

bool CanvasFocus::isBeingEdited(QWidget *focus) const
{
    QWidget *field = textFieldOf(focus);
    if (!field)
        return false;
    if (field == m_editing)
        return true;
    // A list's rename editor lives in the list's viewport while it is open.
    for (QWidget *p = field->parentWidget(); p; p = p->parentWidget())
        if (qobject_cast<QAbstractItemView *>(p))
            return true;
    return false;
}

void CanvasFocus::returnFocus()
{
    if (!m_canvas || !m_window || !m_canvas->isVisible() || !m_canvas->isEnabled())
        return;
    if (QApplication::activePopupWidget() || QApplication::activeModalWidget())
        return;
    QWidget *focus = QApplication::focusWidget();
    if (!focus)
        focus = m_window->focusWidget();
    if (focus == m_canvas || (focus && !belongsToWindow(focus)) || isBeingEdited(focus))
        return;
    m_canvas->setFocus(Qt::OtherFocusReason);
}

} // namespace finbook::ui
