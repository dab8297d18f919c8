// The main window's shading part: the Shading dock (issue 27), shown from View → Panels.
#include "shading_panel.h"

#include <finbook/ui/window/main_window.h>

#include <QDockWidget>
#include <QMenu>

namespace finbook::ui {

void MainWindow::createShading()
{
    auto *panel = new ShadingPanel(m_state);
    auto *dock = new QDockWidget(tr("Shading"), this);
    dock->setObjectName(QStringLiteral("shadingDock"));
    dock->setWidget(panel);
    // Hidden until asked for (View → Panels): the right side keeps its height for the
    // Skeleton panel, the object list and the undo history.
    addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->hide();
    m_docksMenu->addAction(dock->toggleViewAction());
}

} // namespace finbook::ui
