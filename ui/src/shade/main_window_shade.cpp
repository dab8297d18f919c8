// The main window's shading part: the Shading dock (issue 27), a tab beside the Skeleton's.
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
    // A tab beside the Skeleton panel: the right side keeps its height for the object list
    // and the undo history, and the Skeleton tab stays in front.
    auto *skeleton = findChild<QDockWidget *>(QStringLiteral("skeletonDock"));
    if (skeleton) {
        tabifyDockWidget(skeleton, dock);
        skeleton->raise();
    } else {
        addDockWidget(Qt::RightDockWidgetArea, dock);
    }
    m_docksMenu->addAction(dock->toggleViewAction());
}

} // namespace finbook::ui
