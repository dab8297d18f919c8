#include "window_list.h"

#include <finbook/model/document.h>
#include <finbook/ui/window/main_window.h>

#include <QFileInfo>
#include <QUndoStack>

namespace finbook::app {

namespace {
void bringForward(ui::MainWindow *window)
{
    window->show();
    window->setWindowState((window->windowState() & ~Qt::WindowMinimized) | Qt::WindowActive);
    window->raise();
    window->activateWindow();
}

bool samePath(const QString &a, const QString &b)
{
    if (a.isEmpty() || b.isEmpty())
        return false;
    const QString ca = QFileInfo(a).canonicalFilePath(), cb = QFileInfo(b).canonicalFilePath();
    return ca.isEmpty() || cb.isEmpty()
               ? QFileInfo(a).absoluteFilePath() == QFileInfo(b).absoluteFilePath()
               : ca == cb;
}
} // namespace

WindowList::WindowList(std::function<ui::MainWindow *()> makeWindow, QObject *parent)
    : QObject(parent)
    , m_makeWindow(std::move(makeWindow))
{}

void WindowList::add(ui::MainWindow *window)
{
    m_windows << QPointer<ui::MainWindow>(window);
}

QList<ui::MainWindow *> WindowList::windows() const
{
    QList<ui::MainWindow *> open;
    for (const auto &w : m_windows)
        if (w && w->isVisible())
            open << w.data();
    return open;
}

ui::MainWindow *WindowList::windowShowing(const QString &path) const
{
    for (ui::MainWindow *w : windows())
        if (samePath(w->filePath(), path))
            return w;
    return nullptr;
}

// A window whose document was never touched: no file, nothing in its undo history.
ui::MainWindow *WindowList::untouchedWindow() const
{
    for (ui::MainWindow *w : windows())
        if (w->filePath().isEmpty() && w->document()->undoStack()->count() == 0 &&
            w->document()->undoStack()->isClean())
            return w;
    return nullptr;
}

ui::MainWindow *WindowList::newWindow()
{
    ui::MainWindow *window = m_makeWindow ? m_makeWindow() : new ui::MainWindow;
    window->setAttribute(Qt::WA_DeleteOnClose);
    // Cascade from the active window so the new one does not hide it exactly.
    if (!m_windows.isEmpty() && m_windows.last())
        window->move(m_windows.last()->pos() + QPoint(32, 32));
    add(window);
    window->show();
    return window;
}

ui::MainWindow *WindowList::open(const QStringList &files)
{
    if (files.isEmpty()) {
        ui::MainWindow *w = newWindow();
        bringForward(w);
        return w;
    }
    ui::MainWindow *last = nullptr;
    for (const QString &file : files) {
        if (ui::MainWindow *w = windowShowing(file)) {
            bringForward(w);
            last = w;
            continue;
        }
        ui::MainWindow *target = untouchedWindow();
        const bool fresh = target == nullptr;
        if (fresh)
            target = newWindow();
        bringForward(target);
        if (target->openFile(file)) {
            last = target;
        } else if (fresh && target->filePath().isEmpty() &&
                   target->document()->undoStack()->isClean()) {
            target->close(); // the file did not open (the user was told): no empty window
        }
    }
    return last;
}

} // namespace finbook::app
