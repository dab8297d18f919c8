// MainWindow: actions, menus and toolbars.
#include <finbook/model/document.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/dialogs/document_settings_dialog.h>
#include <finbook/ui/dialogs/preferences_dialog.h>
#include <finbook/ui/dialogs/shortcuts_dialog.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/export/export_done.h>
#include <finbook/ui/help/manual_browser.h>
#include <finbook/ui/i18n/action_text.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/layers/cel_editing.h>
#include <finbook/ui/layers/layer_actions.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/reference/reference_panel.h>
#include <finbook/ui/sound/sound_controller.h>
#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/timeline/onion_skin_editor.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

namespace finbook::ui {

QAction *MainWindow::makeAction(const QString &name, const QString &text)
{
    auto *a = new QAction(text, this);
    a->setObjectName(name);
    m_shortcuts->registerAction(a);
    return a;
}

void MainWindow::createActions()
{
    m_frameActions = new FrameActions(m_state, this);
    m_layerActions = new LayerActions(m_state, this, this);
    m_objectActions = new ObjectActions(m_state, this);
    connect(m_objectActions, &ObjectActions::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 8000); });
    m_swapActions = new SwapActions(m_state, this, this);
    connect(m_swapActions, &SwapActions::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 6000); });
    m_playback = new PlaybackController(m_state, this);
    m_sound = new SoundController(m_state, m_playback, this, this);
    m_shortcuts->registerAction(m_sound->importAction());
    connect(m_sound, &SoundController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 6000); });
    connect(m_sound, &SoundController::importFailed, this, &MainWindow::reportError);
    m_fileBar = addToolBar(tr("File"));
    m_fileBar->setObjectName(QStringLiteral("fileToolBar"));
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createFrameAndObjectMenus();
    createToolsMenu();
    createHelpMenu();
}

void MainWindow::createFileMenu()
{
    m_fileMenu = menuBar()->addMenu(tr("&File"));
    QAction *newAction = makeAction(QStringLiteral("file.new"), tr("&New"));
    connect(newAction, &QAction::triggered, this, &MainWindow::newFile);
    QAction *openAction = makeAction(QStringLiteral("file.open"), tr("&Open..."));
    connect(openAction, &QAction::triggered, this, &MainWindow::open);
    QAction *example = makeAction(QStringLiteral("file.openExample"), tr("Open Exa&mple"));
    connect(example, &QAction::triggered, this, &MainWindow::openExample);
    QAction *welcome = makeAction(QStringLiteral("file.welcome"), tr("&Welcome..."));
    connect(welcome, &QAction::triggered, this, &MainWindow::showWelcome);
    m_fileMenu->addAction(welcome);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(newAction);
    m_fileMenu->addAction(openAction);
    m_fileMenu->addAction(example);
    m_recentMenu = m_fileMenu->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
    rebuildRecentMenu();
    QAction *saveAction = makeAction(QStringLiteral("file.save"), tr("&Save"));
    connect(saveAction, &QAction::triggered, this, &MainWindow::save);
    QAction *saveAsAction = makeAction(QStringLiteral("file.saveAs"), tr("Save &As..."));
    connect(saveAsAction, &QAction::triggered, this, &MainWindow::saveAs);
    // One Export entry: the dialog does every format, a folder of PNG frames included. It
    // keeps the id (and so the shortcut) "Export Frames" had.
    QAction *exportAnimation = makeAction(QStringLiteral("file.export"), tr("E&xport..."));
    connect(exportAnimation, &QAction::triggered, this, [this] {
        settlePoses();
        ExportDialog dialog(*m_doc, m_path, this);
        dialog.setCurrentFrame(m_state->currentFrameIndex());
        if (dialog.exec() != QDialog::Accepted)
            return;
        statusBar()->showMessage(dialog.summary());
        const bool page = dialog.options().format == model::ExportFormat::Html;
        const QStringList &files = dialog.writtenFiles();
        showExportDone(this, dialog.summary(), files,
                       page && !files.isEmpty() ? files.first() : QString());
    });
    QAction *importAction = makeAction(QStringLiteral("file.importMesh"), tr("&Import Mesh..."));
    connect(importAction, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Import Mesh"), QFileInfo(m_path).path(), tr("OFF meshes (*.off)"));
        if (!path.isEmpty())
            importMesh(path);
    });
    QAction *pictureAction =
        makeAction(QStringLiteral("file.importPicture"), tr("Import &Picture..."));
    connect(pictureAction, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Import Picture"), QFileInfo(m_path).path(),
            tr("Pictures (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;"
               "OpenRaster stacks (*.ora);;All files (*)"));
        if (!path.isEmpty())
            importPicture(path);
    });
    QAction *referenceAction =
        makeAction(QStringLiteral("file.importReference"), tr("Import Re&ference..."));
    connect(referenceAction, &QAction::triggered, this, [this] {
        const QStringList paths = chooseReferenceFiles(this, QFileInfo(m_path).path());
        if (paths.isEmpty())
            return;
        if (const auto error = importReference(*m_doc, paths))
            reportError(tr("Cannot Import Reference"), *error);
    });
    QAction *quitAction = makeAction(QStringLiteral("file.quit"), tr("&Quit"));
    quitAction->setMenuRole(QAction::QuitRole);
    connect(quitAction, &QAction::triggered, this, &QWidget::close);
    m_fileMenu->addAction(saveAction);
    m_fileMenu->addAction(saveAsAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(importAction);
    m_fileMenu->addAction(pictureAction);
    m_fileMenu->addAction(referenceAction);
    m_fileMenu->addAction(m_sound->importAction());
    m_fileMenu->addAction(exportAnimation);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(quitAction);
    m_fileBar->addActions({newAction, openAction, saveAction});
}

void MainWindow::createEditMenu()
{
    m_editMenu = menuBar()->addMenu(tr("&Edit"));
    QUndoStack *stack = m_doc->undoStack();
    QAction *undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("edit.undo"));
    setShortcutName(undo, tr("Undo"));
    m_shortcuts->registerAction(undo);
    QAction *redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("edit.redo"));
    setShortcutName(redo, tr("Redo"));
    m_shortcuts->registerAction(redo);
    m_editMenu->addActions({undo, redo});
    m_fileBar->addActions({undo, redo});
    m_editMenu->addSeparator();

    const auto report = [this](const QString &problem) {
        if (!problem.isEmpty())
            reportError(tr("Paste"), problem);
    };
    // Cut, Copy and Delete work on the cels picked in the dope sheet when there are some (picking
    // cels drops the picked strokes), else on the picked strokes; Paste pastes what was copied
    // last.
    QAction *cut = makeAction(QStringLiteral("edit.cut"), tr("Cu&t"));
    connect(cut, &QAction::triggered, this, [this] {
        if (!m_state->selectedCels().empty())
            CelEditing::cut(*m_state);
        else
            StrokeEditing::cutSelection(*m_state);
    });
    QAction *copy = makeAction(QStringLiteral("edit.copy"), tr("&Copy"));
    connect(copy, &QAction::triggered, this, [this] {
        if (!m_state->selectedCels().empty())
            CelEditing::copy(*m_state);
        else
            StrokeEditing::copySelection(*m_state);
    });
    QAction *paste = makeAction(QStringLiteral("edit.paste"), tr("&Paste"));
    connect(paste, &QAction::triggered, this, [this, report] {
        QString problem;
        if (CelEditing::clipboardHasCels()) {
            CelEditing::paste(*m_state, &problem);
            report(problem);
            return;
        }
        // A picture (another program's, or pictures copied here): a picture object; with
        // copied strokes too, those come next.
        const QMimeData *mime = QApplication::clipboard()->mimeData();
        if (mime && mime->hasImage()) {
            const bool strokes = StrokeEditing::clipboardHasStrokes();
            if (!pastePicture(qvariant_cast<QImage>(mime->imageData()), m_canvas->cursorPos()) ||
                !strokes)
                return;
        }
        // At the mouse when it is over the canvas; selected, with the select tool's box shown.
        if (StrokeEditing::paste(*m_state, &problem, m_canvas->cursorPos()))
            m_canvas->setCurrentTool(QStringLiteral("tool.select"));
        report(problem);
    });
    QAction *remove = makeAction(QStringLiteral("edit.delete"), tr("&Delete"));
    connect(remove, &QAction::triggered, this, [this] {
        if (!m_state->selectedCels().empty())
            CelEditing::remove(*m_state);
        else
            StrokeEditing::deleteSelection(*m_state);
    });
    QAction *selectAll = makeAction(QStringLiteral("edit.selectAll"), tr("Select &All"));
    connect(selectAll, &QAction::triggered, this, [this] {
        StrokeEditing::selectAll(*m_state);
        // The selection box belongs to the select tool: show it.
        m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    });
    QAction *deselect = makeAction(QStringLiteral("edit.deselect"), tr("Dese&lect"));
    connect(deselect, &QAction::triggered, this, [this] { m_state->setSelectedStrokes({}); });
    m_editMenu->addActions({cut, copy, paste, remove});
    m_editMenu->addSeparator();
    m_editMenu->addActions({selectAll, deselect});
    m_editMenu->addSeparator();
    QAction *docSettings =
        makeAction(QStringLiteral("edit.documentSettings"), tr("D&ocument Settings..."));
    connect(docSettings, &QAction::triggered, this,
            [this] { DocumentSettingsDialog::edit(m_doc, this); });
    QAction *prefs = makeAction(QStringLiteral("edit.preferences"), tr("Pre&ferences..."));
    prefs->setMenuRole(QAction::PreferencesRole);
    connect(prefs, &QAction::triggered, this, &MainWindow::showPreferences);
    m_editMenu->addActions({docSettings, prefs});

    connect(m_state, &EditorState::selectionChanged, this, &MainWindow::updateEditActions);
    connect(m_state, &EditorState::celSelectionChanged, this, &MainWindow::updateEditActions);
    connect(QApplication::clipboard(), &QClipboard::dataChanged, this,
            &MainWindow::updateEditActions);
    updateEditActions();
}

void MainWindow::updateEditActions()
{
    const bool selected = m_state->hasSelection();
    const bool cels = !m_state->selectedCels().empty();
    for (const char *name : {"edit.cut", "edit.copy", "edit.delete"})
        if (QAction *a = action(QString::fromLatin1(name)))
            a->setEnabled(selected || cels);
    if (QAction *a = action(QStringLiteral("edit.deselect")))
        a->setEnabled(selected);
    if (QAction *a = action(QStringLiteral("edit.paste")))
        a->setEnabled(StrokeEditing::clipboardHasStrokes() || CelEditing::clipboardHasCels() ||
                      (QApplication::clipboard()->mimeData() &&
                       QApplication::clipboard()->mimeData()->hasImage()));
}

void MainWindow::createViewMenu()
{
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    QAction *zoomIn = makeAction(QStringLiteral("view.zoomIn"), tr("Zoom &In"));
    connect(zoomIn, &QAction::triggered, m_canvas, &CanvasWidget::zoomIn);
    QAction *zoomOut = makeAction(QStringLiteral("view.zoomOut"), tr("Zoom &Out"));
    connect(zoomOut, &QAction::triggered, m_canvas, &CanvasWidget::zoomOut);
    QAction *fit = makeAction(QStringLiteral("view.fit"), tr("&Fit to Window"));
    connect(fit, &QAction::triggered, m_canvas, &CanvasWidget::fitToView);
    QAction *actual = makeAction(QStringLiteral("view.actualSize"), tr("&Actual Size (100 %)"));
    connect(actual, &QAction::triggered, m_canvas, &CanvasWidget::actualSize);
    m_viewMenu->addActions({zoomIn, zoomOut, fit, actual});
    m_viewMenu->addSeparator();
    // Turning the view (not the drawing), as a sheet of paper is turned to draw a natural curve;
    // Shift+Space-drag turns it freely, and the status bar's Rotation field takes a number.
    QAction *rotateLeft = makeAction(QStringLiteral("view.rotateLeft"), tr("Rotate View &Left"));
    connect(rotateLeft, &QAction::triggered, m_canvas, [this] { m_canvas->rotateBy(-15); });
    QAction *rotateRight = makeAction(QStringLiteral("view.rotateRight"), tr("Rotate View &Right"));
    connect(rotateRight, &QAction::triggered, m_canvas, [this] { m_canvas->rotateBy(15); });
    QAction *resetRotation =
        makeAction(QStringLiteral("view.resetRotation"), tr("R&eset View Rotation"));
    connect(resetRotation, &QAction::triggered, m_canvas, &CanvasWidget::resetRotation);
    // Flipping the view shows the drawing's proportions with fresh eyes; the document is kept.
    QAction *mirror = makeAction(QStringLiteral("view.mirror"), tr("Mirror Vie&w"));
    mirror->setCheckable(true);
    connect(mirror, &QAction::toggled, m_canvas, &CanvasWidget::setMirrored);
    connect(m_canvas, &CanvasWidget::viewTurned, mirror,
            [mirror](qreal, bool mirrored) { mirror->setChecked(mirrored); });
    m_viewMenu->addActions({rotateLeft, rotateRight, resetRotation, mirror});
    m_viewMenu->addSeparator();

    QAction *onion = makeAction(QStringLiteral("view.onionSkin"), tr("O&nion Skin"));
    onion->setCheckable(true);
    onion->setChecked(m_state->onionSkin().enabled);
    connect(onion, &QAction::toggled, this, [this](bool on) {
        OnionSkin o = m_state->onionSkin();
        o.enabled = on;
        m_state->setOnionSkin(o);
    });
    connect(m_state, &EditorState::onionSkinChanged, onion,
            [this, onion] { onion->setChecked(m_state->onionSkin().enabled); });
    QAction *onionSettings =
        makeAction(QStringLiteral("view.onionSkinSettings"), tr("Onion Skin &Settings..."));
    connect(onionSettings, &QAction::triggered, this, &MainWindow::showOnionSkinSettings);
    QAction *mesh = makeAction(QStringLiteral("view.showMesh"), tr("Show &Mesh"));
    mesh->setCheckable(true);
    mesh->setChecked(m_state->showMesh());
    connect(mesh, &QAction::toggled, m_state, &EditorState::setShowMesh);
    connect(m_state, &EditorState::showMeshChanged, mesh, &QAction::setChecked);
    // The shot as the audience will see it: the canvas looks through the camera.
    QAction *cameraView = makeAction(QStringLiteral("view.cameraView"), tr("&Camera View"));
    cameraView->setCheckable(true);
    cameraView->setChecked(m_state->cameraView());
    connect(cameraView, &QAction::toggled, m_state, &EditorState::setCameraView);
    connect(m_state, &EditorState::cameraViewChanged, cameraView, &QAction::setChecked);
    // Layers other than the current one at half strength, so the one being drawn on stands out.
    QAction *dim = makeAction(QStringLiteral("view.dimOtherLayers"), tr("&Dim Other Layers"));
    dim->setCheckable(true);
    dim->setChecked(m_state->dimOtherLayers());
    connect(dim, &QAction::toggled, m_state, &EditorState::setDimOtherLayers);
    connect(m_state, &EditorState::dimOtherLayersChanged, dim, &QAction::setChecked);
    m_viewMenu->addActions({onion, onionSettings, mesh, cameraView, dim});
    m_viewMenu->addSeparator();
    m_docksMenu = m_viewMenu->addMenu(tr("&Panels"));
    m_docksMenu->addAction(m_fileBar->toggleViewAction());
}

void MainWindow::createFrameAndObjectMenus()
{
    QMenu *frameMenu = menuBar()->addMenu(tr("F&rame"));
    connect(m_frameActions, &FrameActions::inbetweensRequested, this,
            &MainWindow::generateInbetweens);
    for (QAction *a : m_frameActions->menuActions()) {
        frameMenu->addAction(a);
        if (!a->isSeparator())
            m_shortcuts->registerAction(a);
    }
    frameMenu->addSeparator();
    for (QAction *a : {m_playback->toggleAction(), m_playback->loopAction()}) {
        frameMenu->addAction(a);
        m_shortcuts->registerAction(a);
    }
    QMenu *layerMenu = menuBar()->addMenu(tr("&Layer"));
    layerMenu->setObjectName(QStringLiteral("layerMenu"));
    for (QAction *a : m_layerActions->menuActions()) {
        layerMenu->addAction(a);
        if (!a->isSeparator())
            m_shortcuts->registerAction(a);
    }
    QMenu *objectMenu = menuBar()->addMenu(tr("&Object"));
    objectMenu->setObjectName(QStringLiteral("objectMenu"));
    for (QAction *a : m_objectActions->menuActions()) {
        objectMenu->addAction(a);
        if (!a->isSeparator() && !a->objectName().isEmpty())
            m_shortcuts->registerAction(a);
    }
    // Drawing substitution: the set's drawings, after the object's own commands.
    objectMenu->addSeparator();
    for (QAction *a : m_swapActions->menuActions()) {
        objectMenu->addAction(a);
        if (a->menu() == nullptr)
            m_shortcuts->registerAction(a);
    }
}

void MainWindow::createToolsMenu()
{
    m_toolsMenu = menuBar()->addMenu(tr("&Tools"));
    m_toolGroup = new QActionGroup(this);
    m_toolGroup->setExclusive(true);
    m_toolsBar = new QToolBar(tr("Tools"), this);
    m_toolsBar->setObjectName(QStringLiteral("toolsToolBar"));
    m_toolsBar->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
    addToolBar(Qt::LeftToolBarArea, m_toolsBar);
}

void MainWindow::createHelpMenu()
{
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    // F1 opens the page about the tool in hand.
    QAction *manual = makeAction(QStringLiteral("help.manual"), tr("Finbook &Manual"));
    connect(manual, &QAction::triggered, this, [this] {
        const CanvasTool *tool = m_canvas->currentTool();
        showManual(ManualBrowser::pageForTool(tool ? tool->id() : QString()));
    });
    QAction *keys = makeAction(QStringLiteral("help.shortcuts"), tr("&Keyboard Shortcuts"));
    connect(keys, &QAction::triggered, this, &MainWindow::showShortcuts);
    QAction *about = makeAction(QStringLiteral("help.about"), tr("&About Finbook"));
    about->setMenuRole(QAction::AboutRole);
    connect(about, &QAction::triggered, this, &MainWindow::showAbout);
    help->addActions({manual, keys, about});
}

void MainWindow::showManual(const QString &page)
{
    if (!m_manual)
        m_manual = new ManualBrowser(this);
    m_manual->openPage(page);
    m_manual->show();
    m_manual->raise();
    m_manual->activateWindow();
}

void MainWindow::showPreferences()
{
    PreferencesDialog dialog(m_prefs, m_shortcuts, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    setPreferences(dialog.preferences());
    m_shortcuts->apply(dialog.shortcuts());
    QSettings settings;
    m_shortcuts->save(settings);
}

void MainWindow::showOnionSkinSettings()
{
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Onion Skin"));
    auto *editor = new OnionSkinEditor(&dialog);
    editor->setOnionSkin(m_state->onionSkin());
    const OnionSkin before = m_state->onionSkin();
    // Live preview: the canvas follows every change; Cancel puts the old settings back.
    connect(editor, &OnionSkinEditor::onionSkinEdited, m_state, &EditorState::setOnionSkin);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto *layout = new QVBoxLayout(&dialog);
    layout->addWidget(editor);
    layout->addWidget(buttons);
    if (dialog.exec() != QDialog::Accepted)
        m_state->setOnionSkin(before);
}

void MainWindow::showShortcuts()
{
    ShortcutsDialog dialog(m_shortcuts, this);
    dialog.exec();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Finbook"),
                       tr("<h3>Finbook %1</h3><p>A flipbook animation editor: draw frame by "
                          "frame, and bend drawings with pins.</p>")
                           .arg(QCoreApplication::applicationVersion()));
}

} // namespace finbook::ui
