// The main window's shading part: the Shading dock (issue 27), shown from View → Panels,
// and the light handle on the canvas while it shows.
#include "shading_panel.h"

#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/shade/light_handle.h>
#include <finbook/ui/window/main_window.h>

#include <QAction>
#include <QDockWidget>
#include <QMenu>

namespace finbook::ui {

namespace {
// Paints the light handle over the frame (the handle itself is the canvas's child).
class LightHandleOverlay : public CanvasOverlay {
public:
    explicit LightHandleOverlay(LightHandle *handle)
        : m_handle(handle)
    {}
    void paint(QPainter &painter, const QTransform &) override { m_handle->paint(painter); }

private:
    LightHandle *m_handle;
};
} // namespace

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
    // It opens as a tab of the Skeleton panel's place (createDocks): asked for, it comes to the
    // front with the light's sun on the canvas, as a docker opened from Krita's or OpenToonz's
    // menu does, rather than behind the Skeleton tab where nothing says it opened.
    connect(dock->toggleViewAction(), &QAction::triggered, dock, [dock](bool shown) {
        if (shown)
            dock->raise();
    });
    // While the panel shows, a sun on the canvas shows the light and drags it.
    m_canvas->addOverlay(std::make_unique<LightHandleOverlay>(new LightHandle(m_canvas, dock)));
}

} // namespace finbook::ui
