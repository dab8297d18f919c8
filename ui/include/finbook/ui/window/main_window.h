// The editor's main window: owns the document and the editor state, the canvas in the
// centre, the timeline (bottom), objects (right) and undo-history docks, menus, toolbars and
// the status bar.
//
// Files: New/Open/Save/Save As/Export Frames, a recent-files menu, and a Save/Discard/Cancel
// prompt before unsaved changes would be lost. The title shows "[*]" while the undo stack is
// not clean. Errors reach the user through reportError() and the Save prompt through
// askToSave(); both are virtual so tests can answer without a modal dialog.
//
// Extending: addTool() puts a CanvasTool on the canvas and gives it an action in the Tools
// menu and toolbar with a registered shortcut (see canvas_tool.h); canvas()->addOverlay()
// adds something drawn over every frame.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/types.h>
#include <finbook/ui/recovery/recovery_dialog.h>
#include <finbook/ui/window/preferences.h>

#include <QImage>
#include <QMainWindow>
#include <QMessageBox>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QActionGroup;
class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QToolBar;

namespace finbook::model {
class Autosaver;
class Document;
class RecoverySession;
} // namespace finbook::model

namespace finbook::ui {

class CanvasTool;
class CanvasWidget;
class ManualBrowser;
class ToolOptionsBar;
class DeformActions;
class CageActions;
class EditorState;
class FrameActions;
class LayerActions;
class ObjectActions;
class SwapActions;
class PenTool;
class SoundController;
class PlaybackController;
class ShortcutRegistry;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kMaxRecentFiles = 10;

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // Opens `path`; on failure tells the user why and keeps the current document.
    bool openFile(const QString &path);
    // Adds a 2D OFF mesh to the current frame as a new object (its outline as strokes), as
    // one undo step. False, with a message, when the file cannot be read.
    bool importMesh(const QString &path);
    // File → Import Picture: the picture (or each visible layer of an OpenRaster stack) as
    // picture objects on top of the current frame, centred on the page, as one undo step. Read
    // and meshed on a worker while a progress dialog shows. False, with a message, when the
    // file cannot be imported.
    bool importPicture(const QString &path);
    // Edit → Paste of a picture another program copied (Krita, GIMP, a browser): a picture
    // object on the current frame, centred at `at` (canvas px) or on the page, one undo step.
    bool pastePicture(const QImage &image, std::optional<QPointF> at = std::nullopt);
    // Saves to `path` and makes it the document's file; false (reported) on failure.
    bool saveFile(const QString &path);
    // Replaces the document with a new one (1 frame, 1 empty object) without asking.
    void newDocument();

    model::Document *document() const { return m_doc; }
    EditorState *editorState() const { return m_state; }
    CanvasWidget *canvas() const { return m_canvas; }
    ShortcutRegistry *shortcuts() const { return m_shortcuts; }
    PenTool *penTool() const { return m_pen; }
    QString filePath() const { return m_path; }
    QStringList recentFiles() const;
    const Preferences &preferences() const { return m_prefs; }
    void setPreferences(const Preferences &preferences);

    // Adds a tool to the canvas, the Tools menu and the tools toolbar; returns its action.
    QAction *addTool(std::unique_ptr<CanvasTool> tool);
    // The action of a tool, or of any registered command, by objectName.
    QAction *action(const QString &objectName) const;

    // Asks to save unsaved changes; true when it is fine to go on (saved or discarded).
    bool maybeSave();

    // The bundled example animation as a new, untitled document (after asking to save).
    bool openExample();
    // The welcome page (WelcomeDialog), not modal; File > Welcome, and at the first start.
    void showWelcome();
    // Shows the Finbook Manual at `page` (ManualBrowser::pages(); F1 opens the current tool's).
    void showManual(const QString &page);
    // Deform > Lip Sync…: keys the current (or the frame's) mouth chart from a sound clip.
    void showLipSync();
    ManualBrowser *manual() const { return m_manual; }

    // Offers the recovery copies that Finbooks which did not close normally left (at start).
    void offerRecovery();
    // Opens a recovery copy as this window's unsaved document. False if the user kept the
    // current document or the copy cannot be read (said to the user).
    bool restoreRecovery(const model::RecoveryCopy &copy);
    model::Autosaver *autosaver() const { return m_autosaver; }
    const model::RecoverySession *recoverySession() const { return m_recovery.get(); }

signals:
    void errorReported(const QString &message);
    // After "Open anyway": what the reader left out or repaired, one sentence each.
    void recoveredProblems(const QStringList &problems);

protected:
    void closeEvent(QCloseEvent *event) override;
    // Files dropped on the window: a .finbook opens (after asking to save the current one),
    // anything else is imported as pictures (importPicture), one file after the other.
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;
    // Shows one sentence to the user (with technical details under "Show Details" when a
    // file would not open). Tests override these to avoid modal dialogs.
    virtual void reportError(const QString &title, const QString &message);
    virtual QMessageBox::StandardButton askToSave();
    // A file that is damaged but partly readable: true to open what is readable of it.
    virtual bool askOpenAnyway(const QString &message);
    struct RecoveryChoice {
        RecoveryDialog::Action action;
        int index; // into the copies offered
    };
    virtual RecoveryChoice askRecovery(const std::vector<model::RecoveryCopy> &copies);
    virtual QString askOpenPath();
    // Import Picture: whether to make a picture's flat background colour transparent.
    virtual bool askKeyOutBackground(const QString &name, QColor background);
    // How far from the background colour a pixel may be and still be keyed out (each channel).
    static constexpr int kKeyOutTolerance = 24;
    virtual QString askSavePath();

private:
    // Picture objects made by `work` on a worker behind a progress dialog saying `reading`,
    // then put on the current frame as one undo step; false (reported under `title`) when
    // `work` fails.
    bool addPictureObjects(
        const std::function<Expected<std::vector<model::StrokeGroup>, QString>()> &work,
        const QString &reading, const QString &title, const std::function<QString(int)> &done);
    // recovery/main_window_recovery.cpp
    void createRecovery();
    void applyAutosaveInterval();
    // main_window.cpp
    void createCanvasAndTools();
    void createDeformation();
    // Every pending converged pose solved now, before the document is saved or exported.
    void settlePoses();
    void createSkeleton(QMenu *deformMenu); // skeleton/main_window_skeleton.cpp
    void createFill();                      // fill/main_window_fill.cpp
    void createShading();                   // shade/main_window_shade.cpp
    void createDocks();
    void createStatusBar();
    void connectStatus();
    void updateTitle();
    void updateStatus();
    void readSettings();
    void writeSettings() const;
    // Restores the pen, the tool and the onion skin of the last run and saves them on change.
    void rememberEditor();
    void toolAdded(CanvasTool *tool);
    // main_window_toolbars.cpp
    void arrangeToolBars();
    QSize defaultSize() const;
    // main_window_menus.cpp
    void createActions();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createFrameAndObjectMenus();
    void createToolsMenu();
    void createHelpMenu();
    void updateEditActions();
    QAction *makeAction(const QString &name, const QString &text);
    void showPreferences();
    void showOnionSkinSettings();
    void showShortcuts();
    void showAbout();
    // inbetween/main_window_inbetween.cpp
    void generateInbetweens(model::Id firstKey, model::Id secondKey);
    // main_window_files.cpp
    void newFile();
    void open();
    bool save();
    bool saveAs();
    bool openRecovering(const QString &path);
    void addRecentFile(const QString &path);
    void rebuildRecentMenu();
    void setFilePath(const QString &path);

    model::Document *m_doc;
    EditorState *m_state;
    ShortcutRegistry *m_shortcuts;
    CanvasWidget *m_canvas = nullptr;
    PenTool *m_pen = nullptr;
    FrameActions *m_frameActions = nullptr;
    LayerActions *m_layerActions = nullptr;
    ObjectActions *m_objectActions = nullptr;
    SwapActions *m_swapActions = nullptr;
    PlaybackController *m_playback = nullptr;
    SoundController *m_sound = nullptr;
    DeformActions *m_deform = nullptr;
    CageActions *m_cage = nullptr;
    Preferences m_prefs;
    QString m_path;
    std::unique_ptr<model::RecoverySession> m_recovery;
    model::Autosaver *m_autosaver = nullptr;
    QString m_errorDetails; // for the reportError() call in progress only

    QMenu *m_fileMenu = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_docksMenu = nullptr;
    QMenu *m_toolsMenu = nullptr;
    QToolBar *m_toolsBar = nullptr;
    QToolBar *m_fileBar = nullptr;
    QActionGroup *m_toolGroup = nullptr;

    QLabel *m_toolLabel = nullptr;
    QLabel *m_frameLabel = nullptr;
    QLabel *m_zoomLabel = nullptr;
    QDoubleSpinBox *m_rotationBox = nullptr; // the view's turn, typed or shown
    ManualBrowser *m_manual = nullptr;       // made when first opened
    ToolOptionsBar *m_options = nullptr;     // the options of the tool in hand
    QLabel *m_cursorLabel = nullptr;
};

} // namespace finbook::ui
