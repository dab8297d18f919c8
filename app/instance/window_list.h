// The editor windows of this Finbook, and where a file the desktop asks to open goes: to the
// window that already shows it (brought forward), else to an untouched new window (nothing
// drawn, never saved), else to a new window. A window's document is never replaced, so a
// request can never lose unsaved work.
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>

#include <functional>

namespace finbook::ui {
class MainWindow;
}

namespace finbook::app {

class WindowList : public QObject {
    Q_OBJECT
public:
    // New windows come from `makeWindow` (tests answer dialogs there); by default plain
    // editor windows.
    explicit WindowList(std::function<ui::MainWindow *()> makeWindow = {},
                        QObject *parent = nullptr);

    // Adds a window the caller made (the first one); it is not deleted here.
    void add(ui::MainWindow *window);
    // The windows still open.
    QList<ui::MainWindow *> windows() const;

    // Opens each file as above; with no file, opens a new empty window. Returns the window
    // that shows the last file (or the new window); nullptr when nothing could be opened.
    ui::MainWindow *open(const QStringList &files);

private:
    ui::MainWindow *windowShowing(const QString &path) const;
    ui::MainWindow *untouchedWindow() const;
    ui::MainWindow *newWindow();

    std::function<ui::MainWindow *()> m_makeWindow;
    QList<QPointer<ui::MainWindow>> m_windows;
};

} // namespace finbook::app
