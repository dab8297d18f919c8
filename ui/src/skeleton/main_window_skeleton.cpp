// The main window's skeleton parts: the Bone tool, View → Show Skeleton, the Skeleton panel,
// Deform → Reset Bone Pose and Edit Joints (both act through the Bone tool), and
// Deform → Skinning (rigid or linear blend for the current object).
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/skeleton/skeleton_overlay.h>
#include <finbook/ui/skeleton/skeleton_panel.h>
#include <finbook/ui/skeleton/tool_bone.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>
#include <finbook/ui/window/tool_options_bar.h>

#include <QActionGroup>
#include <QDockWidget>
#include <QMenu>
#include <QStatusBar>
#include <QToolBar>

namespace finbook::ui {

void MainWindow::createSkeleton(QMenu *deformMenu)
{
    auto boneTool = std::make_unique<BoneTool>(m_deform->controller());
    BoneTool *bones = boneTool.get();
    QAction *boneAction = addTool(std::move(boneTool));

    deformMenu->addSeparator();
    QAction *resetBone = makeAction(QStringLiteral("deform.resetBone"), tr("Reset &Bone Pose"));
    resetBone->setStatusTip(tr("Turn the bone selected with the Bone tool back to rest; the "
                               "bones below it keep their bends"));
    connect(resetBone, &QAction::triggered, bones, &BoneTool::resetSelectedBone);
    deformMenu->addAction(resetBone);
    QAction *editJoints = makeAction(QStringLiteral("deform.editJoints"), tr("&Edit Joints"));
    editJoints->setCheckable(true);
    editJoints->setStatusTip(tr("With the Bone tool, move, insert and delete the joints of an "
                                "unposed skeleton instead of posing it"));
    connect(editJoints, &QAction::toggled, this, [bones, boneAction](bool on) {
        bones->setEditJoints(on);
        if (on && !boneAction->isChecked())
            boneAction->trigger();
    });
    connect(bones, &BoneTool::editJointsChanged, editJoints, &QAction::setChecked);
    deformMenu->addAction(editJoints);
    const auto syncReset = [resetBone, bones] {
        resetBone->setEnabled(bones->canResetSelectedBone());
    };
    connect(bones, &BoneTool::selectionChanged, resetBone, syncReset);
    connect(m_state, &EditorState::currentFrameChanged, resetBone, syncReset);
    connect(m_doc, &model::Document::constraintsChanged, resetBone, syncReset);
    connect(m_doc, &model::Document::documentReset, resetBone, syncReset);
    syncReset();

    auto overlay = std::make_unique<SkeletonOverlay>(m_state, m_canvas);
    SkeletonOverlay *skeletons = overlay.get();
    m_canvas->addOverlay(std::move(overlay));
    QAction *show = makeAction(QStringLiteral("view.showSkeleton"), tr("Show S&keleton"));
    show->setCheckable(true);
    connect(show, &QAction::toggled, skeletons, &SkeletonOverlay::setShown);
    m_viewMenu->insertAction(action(QStringLiteral("view.showMesh")), show);

    auto *panel = new SkeletonPanel(m_state);
    auto *dock = new QDockWidget(tr("Skeleton"), this);
    dock->setObjectName(QStringLiteral("skeletonDock"));
    dock->setWidget(panel);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    m_docksMenu->addAction(dock->toggleViewAction());
    connect(panel, &SkeletonPanel::messagePosted, this,
            [this](const QString &message) { statusBar()->showMessage(message, 6000); });

    QMenu *skinning = deformMenu->addMenu(tr("S&kinning"));
    auto *group = new QActionGroup(skinning);
    const struct {
        model::SkinningMode mode;
        QString name;
        QString text;
    } modes[] = {{model::SkinningMode::Rigid, QStringLiteral("deform.skinningRigid"),
                  tr("&Rigid (Bones Pin the Mesh)")},
                 {model::SkinningMode::LinearBlend, QStringLiteral("deform.skinningLinear"),
                  tr("&Linear Blend")},
                 {model::SkinningMode::CutOut, QStringLiteral("deform.skinningCutOut"),
                  tr("&Cut-out (Limbs Turn over the Body)")}};
    std::vector<std::pair<QAction *, model::SkinningMode>> choices;
    for (const auto &m : modes) {
        QAction *a = makeAction(m.name, m.text);
        a->setCheckable(true);
        group->addAction(a);
        skinning->addAction(a);
        const model::SkinningMode mode = m.mode;
        connect(a, &QAction::triggered, this, [this, mode] {
            const model::StrokeGroup *g = m_state->currentGroup();
            if (g && !g->rig.skeleton.empty())
                m_doc->undoStack()->push(new model::SetSkinningModeCommand(m_doc, g->id, mode));
        });
        choices.emplace_back(a, mode);
    }
    auto sync = [this, skinning, choices] {
        const model::StrokeGroup *g = m_state->currentGroup();
        const bool has = g && !g->rig.skeleton.empty();
        skinning->setEnabled(has);
        for (const auto &[a, mode] : choices) {
            a->setChecked(has && g->rig.skeleton.mode == mode);
            a->setEnabled(has);
        }
    };
    connect(m_state, &EditorState::currentGroupChanged, skinning, sync);
    connect(m_state, &EditorState::currentFrameChanged, skinning, sync);
    connect(m_doc, &model::Document::constraintsChanged, skinning, sync);
    sync();

    // The Bone tool's options: the skinning, the refinement sliders and the actions on a rig.
    QToolBar *page =
        m_options->newPage(QStringLiteral("boneOptions"), {QStringLiteral("tool.bone")});
    const QString shortNames[] = {tr("Rigid"), tr("Blend"), tr("Cut-out")};
    for (std::size_t i = 0; i < choices.size(); ++i) {
        choices[i].first->setIconText(shortNames[i]);
        page->addAction(choices[i].first);
    }
    page->addSeparator();
    auto *sliders = new SkeletonPanel(m_state, page, true);
    connect(sliders, &SkeletonPanel::messagePosted, this,
            [this](const QString &message) { statusBar()->showMessage(message, 6000); });
    page->addWidget(sliders);
    page->addSeparator();
    page->addActions(m_deform->actions());
}

} // namespace finbook::ui
