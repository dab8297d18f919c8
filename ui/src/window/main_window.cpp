// MainWindow: construction, docks, status bar, title and settings. Menus are in
// main_window_menus.cpp, file handling in main_window_files.cpp.
#include <finbook/model/document.h>
#include <finbook/model/recovery/autosaver.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/ui/camera/camera_frame_overlay.h>
#include <finbook/ui/camera/tool_camera.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/i18n/action_text.h>
#include <finbook/ui/keys/canvas_focus.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/layers/layer_sheet.h>
#include <finbook/ui/palette/palette_panel.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/panels/objects_panel.h>
#include <finbook/ui/reference/reference_panel.h>
#include <finbook/ui/reference/tool_reference.h>
#include <finbook/ui/sound/sound_row.h>
#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/swap/swap_picker.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/timeline/timeline_widget.h>
#include <finbook/ui/tools/brush_tool_bar.h>
#include <finbook/ui/tools/eraser_tool_bar.h>
#include <finbook/ui/tools/tool_eraser.h>
#include <finbook/ui/tools/tool_eyedropper.h>
#include <finbook/ui/tools/tool_hand.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/tools/tool_select.h>
#include <finbook/ui/window/editor_memory.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>
#include <finbook/ui/window/tool_options_bar.h>

#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoView>

#include <cmath>

namespace finbook::ui {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_doc(new model::Document(this))
    , m_state(new EditorState(m_doc, this))
    , m_shortcuts(new ShortcutRegistry(this))
{
    setObjectName(QStringLiteral("mainWindow"));
    setAcceptDrops(true);
    {
        QSettings settings;
        m_prefs = Preferences::load(settings);
    }
    m_state->setOnionSkin(m_prefs.onionSkin);
    newDocument();
    m_canvas = new CanvasWidget(m_state, this);
    setCentralWidget(m_canvas);
    new CanvasFocus(this, m_canvas);
    createActions();
    createCanvasAndTools();
    createDeformation();
    createFill();
    createShading();
    createDocks();
    createStatusBar();
    arrangeToolBars();
    readSettings();
    rememberEditor();
    connect(m_doc->undoStack(), &QUndoStack::cleanChanged, this,
            [this](bool clean) { setWindowModified(!clean); });
    createRecovery();
    updateTitle();
    // Toolbar buttons and tooltips show texts Qt derives from the actions' texts, which keep a
    // Japanese "(&S)" as "(S)".
    keepIconTextsPlain(this);
    m_canvas->setFocus();
}

MainWindow::~MainWindow()
{
    // Before the document (a child, deleted later by QObject) clears its undo stack, which
    // says "clean" and would discard the copy that quitting with unsaved changes must keep.
    delete m_autosaver;
    m_autosaver = nullptr;
}

void MainWindow::createCanvasAndTools()
{
    connect(m_canvas, &CanvasWidget::toolAdded, this, &MainWindow::toolAdded);
    connect(m_canvas, &CanvasWidget::currentToolChanged, this, [this](CanvasTool *tool) {
        if (QAction *a = action(tool->id()))
            a->setChecked(true);
        updateStatus();
    });
    auto pen = std::make_unique<PenTool>();
    m_pen = pen.get();
    addTool(std::move(pen));
    auto eraser = std::make_unique<EraserTool>();
    EraserTool *eraserTool = eraser.get();
    addTool(std::move(eraser));
    addTool(std::make_unique<SelectTool>());
    addTool(std::make_unique<EyedropperTool>(m_pen));
    addTool(std::make_unique<HandTool>());
    addTool(std::make_unique<ReferenceTool>());
    addTool(std::make_unique<CameraTool>());
    m_canvas->addOverlay(std::make_unique<CameraFrameOverlay>(m_canvas));
    // One options bar follows the tool in hand; each tool adds its page (here the pen's, which
    // the eyedropper shares, and the eraser's; the deformers and the fill add theirs).
    m_options = new ToolOptionsBar(m_canvas, this);
    addToolBar(Qt::TopToolBarArea, m_options);
    m_docksMenu->addAction(m_options->toggleViewAction());
    auto *brush = new BrushToolBar(m_pen, this);
    brush->setObjectName(QStringLiteral("penOptions"));
    brush->setMovable(false);
    m_options->addPage(brush, {QStringLiteral("tool.pen"), QStringLiteral("tool.eyedropper")});
    // Its swatches are the document palette's first colours.
    const auto showPalette = [this, brush] { brush->setPalette(m_doc->palette()); };
    connect(m_doc, &model::Document::paletteChanged, brush, showPalette);
    connect(m_doc, &model::Document::documentReset, brush, showPalette);
    showPalette();
    auto *eraserBar = new EraserToolBar(eraserTool, this);
    eraserBar->setObjectName(QStringLiteral("eraserOptions"));
    eraserBar->setMovable(false);
    m_options->addPage(eraserBar, {QStringLiteral("tool.eraser")});
    m_docksMenu->addAction(m_toolsBar->toggleViewAction());
}

QAction *MainWindow::addTool(std::unique_ptr<CanvasTool> tool)
{
    const QString id = tool->id();
    m_canvas->addTool(std::move(tool));
    return action(id);
}

void MainWindow::toolAdded(CanvasTool *tool)
{
    auto *a = new QAction(tool->icon(), tool->name(), this);
    a->setObjectName(tool->id());
    a->setCheckable(true);
    a->setShortcut(tool->defaultShortcut());
    // "Bone (K): build a skeleton and pose the drawing by its bones": what the tool does and
    // its key, the key as the shortcut preferences have it now.
    const auto tip = [a, tool] {
        const QString keys = a->shortcut().toString(QKeySequence::NativeText);
        const QString named =
            keys.isEmpty() ? tool->name() : MainWindow::tr("%1 (%2)").arg(tool->name(), keys);
        return tool->description().isEmpty()
                   ? named
                   : MainWindow::tr("%1: %2").arg(named, tool->description());
    };
    a->setToolTip(tip());
    m_toolGroup->addAction(a);
    m_toolsMenu->addAction(a);
    m_toolsBar->addAction(a);
    m_shortcuts->registerAction(a);
    const QString id = tool->id();
    connect(a, &QAction::triggered, m_canvas, [this, id] { m_canvas->setCurrentTool(id); });
    connect(m_shortcuts, &ShortcutRegistry::shortcutsChanged, a,
            [a, tip] { a->setToolTip(tip()); });
    if (m_canvas->currentTool() == tool)
        a->setChecked(true);
}

QAction *MainWindow::action(const QString &objectName) const
{
    return m_shortcuts->action(objectName);
}

void MainWindow::createDocks()
{
    const auto dock = [this](QWidget *content, const QString &name, const QString &title,
                             Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(title, this);
        d->setObjectName(name);
        content->setParent(d);
        d->setWidget(content);
        addDockWidget(area, d);
        m_docksMenu->addAction(d->toggleViewAction());
        return d;
    };
    auto *timeline = new TimelineWidget(m_state, m_frameActions, m_playback);
    {
        // A frame's menu also swaps the drawing it shows (drawing substitution).
        QList<QAction *> frameMenu = m_frameActions->menuActions();
        auto *separator = new QAction(timeline);
        separator->setSeparator(true);
        frameMenu << separator << m_swapActions->drawingMenu()->menuAction()
                  << m_swapActions->action(QStringLiteral("swap.previous"))
                  << m_swapActions->action(QStringLiteral("swap.next"));
        timeline->view()->setMenuActions(frameMenu);
    }
    timeline->addBelowFrames(new SoundRow(m_sound, timeline->view()));
    // The dope sheet: a row per layer over the current layer's thumbnails.
    auto *sheet = new QScrollArea;
    sheet->setObjectName(QStringLiteral("layerSheetScroll"));
    auto *layerSheet = new LayerSheet(m_state, m_layerActions);
    layerSheet->setCelMenu([this](QMenu *menu, model::Id cel) {
        // A cel showing a swappable object: the drawings it may show.
        const model::Frame *frame = m_doc->frame(cel);
        if (!frame)
            return;
        for (auto it = frame->groups.rbegin(); it != frame->groups.rend(); ++it)
            if (it->swap.linked()) {
                QMenu *drawings = menu->addMenu(tr("Show Dr&awing"));
                m_swapActions->fillDrawingMenu(drawings, it->id);
                return;
            }
    });
    sheet->setWidget(layerSheet);
    sheet->setWidgetResizable(true);
    sheet->setFrameShape(QFrame::NoFrame);
    // As tall as its rows (up to five, then it scrolls), so every layer of a small scene shows.
    const auto fitSheet = [this, sheet] {
        const int rows = std::clamp(m_doc->layerCount(), 1, 5);
        sheet->setFixedHeight(LayerSheet::kRulerHeight + rows * LayerSheet::kRowHeight + 2 +
                              sheet->horizontalScrollBar()->sizeHint().height());
    };
    for (auto signal : {&model::Document::layersChanged, &model::Document::documentReset})
        connect(m_doc, signal, sheet, fitSheet);
    fitSheet();
    timeline->addAboveFrames(sheet);
    dock(timeline, QStringLiteral("timelineDock"), tr("Timeline"), Qt::BottomDockWidgetArea);
    auto *objects = new ObjectsPanel(m_state, m_objectActions);
    objects->addFooter(new SwapPicker(m_state, m_swapActions));
    dock(objects, QStringLiteral("objectsDock"), tr("Objects"), Qt::RightDockWidgetArea);
    m_swapActions->setChartCentre(
        [this] { return m_canvas->mapToCanvas(QRectF(m_canvas->rect()).center()); });
    QDockWidget *reference = dock(new ReferencePanel(m_doc), QStringLiteral("referenceDock"),
                                  tr("Reference"), Qt::RightDockWidgetArea);
    // The panels shown only when wanted (Reference, Shading) share the Skeleton panel's place
    // as tabs: the right side keeps its height for the object list and the undo history, and
    // the timeline its height for the thumbnails and the sound row, even on a small screen.
    if (auto *skeleton = findChild<QDockWidget *>(QStringLiteral("skeletonDock")))
        for (const char *name : {"shadingDock", "referenceDock"})
            if (auto *tab = findChild<QDockWidget *>(QString::fromLatin1(name))) {
                const bool hidden = tab->isHidden();
                tabifyDockWidget(skeleton, tab);
                tab->setHidden(hidden);
            }
    reference->hide(); // File → Import Reference shows it
    connect(&m_doc->referenceLayer(), &model::ReferenceLayer::referenceChanged, reference,
            [this, reference] {
                if (!m_doc->referenceLayer().isEmpty() && !reference->isVisible()) {
                    reference->show();
                    reference->raise();
                }
            });
    auto *history = new QUndoView(m_doc->undoStack());
    history->setEmptyLabel(tr("<opened document>"));
    QDockWidget *historyDock =
        dock(history, QStringLiteral("historyDock"), tr("Undo History"), Qt::RightDockWidgetArea);
    // The palette shares the history's place as a tab, in front: it is what a drawing day
    // reaches for more often.
    auto *palette = new PalettePanel(m_doc, m_pen);
    connect(palette, &PalettePanel::messagePosted, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    QDockWidget *paletteDock =
        dock(palette, QStringLiteral("paletteDock"), tr("Palette"), Qt::RightDockWidgetArea);
    tabifyDockWidget(historyDock, paletteDock);
    paletteDock->raise();
}

void MainWindow::createStatusBar()
{
    m_toolLabel = new QLabel(this);
    m_frameLabel = new QLabel(this);
    m_zoomLabel = new QLabel(this);
    m_cursorLabel = new QLabel(this);
    m_cursorLabel->setMinimumWidth(110);
    for (QLabel *label : {m_toolLabel, m_frameLabel, m_zoomLabel, m_cursorLabel}) {
        label->setContentsMargins(8, 0, 8, 0);
        label->setAlignment(Qt::AlignCenter);
        statusBar()->addPermanentWidget(label);
    }
    m_zoomLabel->setMinimumWidth(60);
    // The view's turn: shown as it changes, and typed to turn it (wrapping past ±180°).
    m_rotationBox = new QDoubleSpinBox(this);
    m_rotationBox->setObjectName(QStringLiteral("viewRotation"));
    m_rotationBox->setRange(-180.0, 180.0);
    m_rotationBox->setDecimals(1);
    m_rotationBox->setSingleStep(15.0);
    m_rotationBox->setWrapping(true);
    m_rotationBox->setSuffix(QStringLiteral("°"));
    m_rotationBox->setPrefix(tr("Rotation "));
    m_rotationBox->setFrame(false);
    m_rotationBox->setKeyboardTracking(false);
    m_rotationBox->setToolTip(
        tr("The view's rotation: the drawing is not changed. Shift+Space-drag on the canvas "
           "turns it freely; 4 and 6 turn it by 15°, 5 resets it, Shift+M mirrors it."));
    statusBar()->insertPermanentWidget(3, m_rotationBox); // after the zoom
    connect(m_rotationBox, &QDoubleSpinBox::valueChanged, m_canvas,
            qOverload<qreal>(&CanvasWidget::setRotation));
    connect(m_canvas, &CanvasWidget::viewTurned, m_rotationBox, [this](qreal rotation, bool) {
        const QSignalBlocker quiet(m_rotationBox);
        m_rotationBox->setValue(rotation);
    });
    connectStatus();
    updateStatus();
}

void MainWindow::connectStatus()
{
    connect(m_canvas, &CanvasWidget::zoomChanged, this, &MainWindow::updateStatus);
    connect(m_state, &EditorState::currentFrameChanged, this, &MainWindow::updateStatus);
    connect(m_doc, &model::Document::framesInserted, this, &MainWindow::updateStatus);
    connect(m_doc, &model::Document::framesRemoved, this, &MainWindow::updateStatus);
    connect(m_doc, &model::Document::documentReset, this, &MainWindow::updateStatus);
    connect(m_canvas, &CanvasWidget::messagePosted, this,
            [this](const QString &message) { statusBar()->showMessage(message, 6000); });
    // Said once per reference: the document opens and plays without it.
    connect(&m_doc->referenceLayer(), &model::ReferenceLayer::mediaFailed, this,
            [this](const QString &name, const QString &why) {
                statusBar()->showMessage(
                    tr("The reference \"%1\" cannot be shown: %2").arg(name, why), 15000);
            });
    connect(m_canvas, &CanvasWidget::cursorMoved, this, [this](const QPointF &p) {
        // lround is undefined past what a long holds: a position a tablet reports far away
        // (or not at all) shows as nothing rather than as a garbage number.
        const auto shown = [](qreal v) { return std::isfinite(v) && std::abs(v) < 1e9; };
        if (!shown(p.x()) || !shown(p.y()))
            m_cursorLabel->clear();
        else
            m_cursorLabel->setText(tr("%1, %2 px").arg(std::lround(p.x())).arg(std::lround(p.y())));
    });
}

void MainWindow::updateStatus()
{
    if (!m_toolLabel)
        return;
    const CanvasTool *tool = m_canvas->currentTool();
    m_toolLabel->setText(tool ? tool->name() : QString());
    m_frameLabel->setText(
        tr("Frame %1 / %2").arg(m_state->currentFrameIndex() + 1).arg(m_doc->frameCount()));
    m_zoomLabel->setText(tr("%1 %").arg(std::lround(m_canvas->zoom() * 100)));
}

void MainWindow::updateTitle()
{
    const QString name = m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
    setWindowTitle(tr("%1[*] - Finbook").arg(name));
    setWindowModified(!m_doc->undoStack()->isClean());
    if (m_autosaver)
        m_autosaver->setDocumentInfo(name, m_path);
}

void MainWindow::readSettings()
{
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray()))
        resize(defaultSize());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    m_shortcuts->load(settings);
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    m_shortcuts->save(settings);
    m_prefs.save(settings);
}

void MainWindow::setPreferences(const Preferences &preferences)
{
    m_prefs = preferences;
    QSettings settings;
    m_prefs.save(settings);
    m_state->setOnionSkin(m_prefs.onionSkin); // the Onion Skin page edits the current one
    applyAutosaveInterval();
}

void MainWindow::rememberEditor()
{
    {
        QSettings settings;
        const EditorMemory memory = EditorMemory::load(settings);
        m_pen->setSettings(memory.pen);
        if (!memory.tool.isEmpty())
            m_canvas->setCurrentTool(memory.tool); // an unknown id keeps the first tool
    }
    // Saved as they change, so a crash or a kill loses nothing either.
    const auto savePenAndTool = [this] {
        EditorMemory memory{m_pen->settings(), {}};
        if (const CanvasTool *tool = m_canvas->currentTool())
            memory.tool = tool->id();
        QSettings settings;
        memory.save(settings);
    };
    connect(m_pen, &PenTool::settingsChanged, this, savePenAndTool);
    connect(m_canvas, &CanvasWidget::currentToolChanged, this, savePenAndTool);
    connect(m_state, &EditorState::onionSkinChanged, this, [this] {
        m_prefs.onionSkin = m_state->onionSkin();
        QSettings settings;
        m_prefs.save(settings);
    });
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    m_autosaver->discard(); // closed on purpose: nothing to recover
    event->accept();
}

} // namespace finbook::ui
