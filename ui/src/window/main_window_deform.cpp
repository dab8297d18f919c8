// The main window's deformation parts: the Pin tool, Show Mesh, the Deform menu and toolbar,
// and a busy indicator while a precompute runs on the worker thread.
#include <finbook/ui/cage/cage_actions.h>
#include <finbook/ui/cage/tool_cage.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/canvas/mesh_overlay.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/pins/tool_pin.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QDoubleSpinBox>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

namespace finbook::ui {

void MainWindow::createDeformation()
{
    m_deform = new DeformActions(m_state, this);
    model::DeformController *controller = m_deform->controller();
    addTool(std::make_unique<PinTool>(controller));
    auto cageTool = std::make_unique<CageTool>(controller);
    CageTool *cage = cageTool.get();
    addTool(std::move(cageTool));
    m_cage = new CageActions(m_state, controller, cage, this);
    m_canvas->addOverlay(std::make_unique<MeshOverlay>(m_state, controller, m_canvas));
    m_canvas->addOverlay(std::make_unique<CageOverlay>(m_state, cage));

    auto *menu = new QMenu(tr("&Deform"), this);
    menuBar()->insertMenu(m_toolsMenu->menuAction(), menu);
    for (QAction *a : m_deform->actions()) {
        menu->addAction(a);
        m_shortcuts->registerAction(a);
    }
    menu->addSeparator();
    for (QAction *a : m_cage->actions()) {
        menu->addAction(a);
        m_shortcuts->registerAction(a);
    }
    menu->addSeparator();
    menu->addMenu(m_deform->createRigidityMenu(menu));
    createSkeleton(menu);

    auto *bar = new QToolBar(tr("Deform"), this);
    bar->setObjectName(QStringLiteral("deformToolBar"));
    bar->addWidget(m_deform->createDensitySpinBox(bar));
    bar->addActions(m_deform->actions());
    bar->addSeparator();
    bar->addWidget(m_cage->createCornersSpinBox(bar));
    bar->addActions(m_cage->actions());
    addToolBar(Qt::TopToolBarArea, bar);
    m_docksMenu->addAction(bar->toggleViewAction());

    // Busy: an indeterminate bar while the worker prepares meshes and factorizations. The
    // window stays usable; pins can be dragged and the drawing catches up when it is ready.
    auto *busy = new QProgressBar(this);
    busy->setObjectName(QStringLiteral("deformBusy"));
    busy->setRange(0, 0);
    busy->setMaximumWidth(90);
    busy->setToolTip(tr("Preparing the deformation…"));
    busy->hide();
    statusBar()->addWidget(busy);
    connect(controller, &model::DeformController::busyChanged, busy, &QWidget::setVisible);
    const auto post = [this](const QString &message) {
        if (message.isEmpty())
            statusBar()->clearMessage();
        else
            statusBar()->showMessage(message, 6000);
    };
    connect(m_deform, &DeformActions::messagePosted, this, post);
    connect(m_cage, &CageActions::messagePosted, this, post);
}

void MainWindow::settlePoses()
{
    if (m_deform)
        m_deform->controller()->settle();
}

} // namespace finbook::ui
