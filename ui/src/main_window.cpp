#include <finbook/ui/main_window.h>

namespace finbook::ui {

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent) {}
MainWindow::~MainWindow() = default;
bool MainWindow::openFile(const QString &) { return false; }

} // namespace finbook::ui
