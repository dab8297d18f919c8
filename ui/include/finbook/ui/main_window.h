// The editor's main window. (Skeleton: the editor issue fills in tools, docks and menus.)
#pragma once

#include <QMainWindow>

namespace finbook::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;
    // Opens `path`; on failure tells the user why and keeps the current document.
    bool openFile(const QString &path);
};

} // namespace finbook::ui
