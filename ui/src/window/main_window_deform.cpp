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
#include <finbook/ui/window/tool_options_bar.h>

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
    menu->addSeparator();
    QAction *lipSync = makeAction(QStringLiteral("deform.lipSync"), tr("&Lip Sync..."));
    lipSync->setToolTip(tr("Key a mouth chart's drawings from the soundtrack"));
    connect(lipSync, &QAction::triggered, this, &MainWindow::showLipSync);
    menu->addAction(lipSync);

    // The pins' and the cage's options, each with the actions on a rig (apply, remove, reset).
    QToolBar *pins = m_options->newPage(QStringLiteral("pinOptions"), {QStringLiteral("tool.pin")});
    pins->addWidget(m_deform->createDensitySpinBox(pins));
    pins->addSeparator();
    pins->addActions(m_deform->actions());
    QToolBar *cagePage =
        m_options->newPage(QStringLiteral("cageOptions"), {QStringLiteral("tool.cage")});
    cagePage->addWidget(m_cage->createCornersSpinBox(cagePage));
    cagePage->addActions(m_cage->actions());
    cagePage->addSeparator();
    cagePage->addActions(m_deform->actions());

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
