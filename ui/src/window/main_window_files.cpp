// MainWindow: new, open, save and the recent-files list (File → Export is export/).
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/import/mesh_import.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/picture/picture_shape.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/ui/dialogs/file_messages.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>
#include <finbook/ui/window/welcome_dialog.h>

#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMenu>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QThread>
#include <QUrl>

namespace finbook::ui {

namespace {
const QString kRecentKey = QStringLiteral("recentFiles");

QString fileFilter()
{
    return MainWindow::tr("Finbook animations (*.finbook);;All files (*)");
}
} // namespace

void MainWindow::newDocument()
{
    // Built directly rather than through InsertFrameCommand: a new document has nothing to undo.
    model::Frame frame;
    frame.id = 1;
    model::StrokeGroup group;
    group.id = 2;
    group.name = tr("Object");
    frame.groups.push_back(std::move(group));
    model::DocumentSettings settings;
    settings.canvasSize = m_prefs.canvasSize;
    settings.fps = m_prefs.frameRate;
    std::vector<model::Frame> frames;
    frames.push_back(std::move(frame));
    m_doc->reset(std::move(frames), model::sanitizedSettings(settings), 3);
    setFilePath(QString());
}

void MainWindow::newFile()
{
    if (maybeSave())
        newDocument();
}

void MainWindow::open()
{
    if (!maybeSave())
        return;
    const QString path = askOpenPath();
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::openFile(const QString &path)
{
    auto loaded = model::loadFinbook(path);
    if (!loaded) {
        const FileProblem problem = FileMessages::openProblem(path, loaded.error());
        m_errorDetails = problem.details;
        const bool anyway =
            model::isRecoverable(loaded.error().code) && askOpenAnyway(problem.text);
        if (!model::isRecoverable(loaded.error().code))
            reportError(tr("Cannot Open File"), problem.text);
        m_errorDetails.clear();
        return anyway && openRecovering(path);
    }
    model::adoptLoadedDocument(*m_doc, std::move(*loaded));
    setFilePath(QFileInfo(path).absoluteFilePath());
    addRecentFile(m_path);
    return true;
}

bool MainWindow::openExample()
{
    if (!maybeSave())
        return false;
    // The example is inside the executable: it opens as a new, untitled animation, so saving
    // asks where (an installed example is read-only anyway).
    QFile file(QStringLiteral(":/examples/walk.finbook"));
    if (!file.open(QIODevice::ReadOnly)) {
        reportError(tr("Cannot Open the Example"), file.errorString());
        return false;
    }
    auto loaded = model::readFinbook(file.readAll());
    if (!loaded) {
        reportError(tr("Cannot Open the Example"), loaded.error().message);
        return false;
    }
    model::adoptLoadedDocument(*m_doc, std::move(*loaded));
    setFilePath(QString());
    statusBar()->showMessage(tr("The example walk cycle: change it and save it as your own."),
                             8000);
    return true;
}

void MainWindow::showWelcome()
{
    auto *welcome = new WelcomeDialog(recentFiles(), this);
    welcome->setAttribute(Qt::WA_DeleteOnClose);
    connect(welcome, &WelcomeDialog::newRequested, this, &MainWindow::newFile);
    connect(welcome, &WelcomeDialog::openRequested, this, &MainWindow::open);
    connect(welcome, &WelcomeDialog::exampleRequested, this, &MainWindow::openExample);
    connect(welcome, &WelcomeDialog::recentRequested, this, [this](const QString &path) {
        if (maybeSave())
            openFile(path);
    });
    connect(welcome, &WelcomeDialog::manualRequested, this, &MainWindow::showManual);
    welcome->show();
}

// "Open anyway": what is readable of a damaged file, as a new unsaved document, so saving it
// can never replace the damaged file (or its backup) without the user choosing where.
bool MainWindow::openRecovering(const QString &path)
{
    QStringList problems;
    auto loaded = model::loadFinbookRecovering(path, &problems);
    if (!loaded) {
        reportError(tr("Cannot Open File"), loaded.error().message);
        return false;
    }
    model::adoptLoadedDocument(*m_doc, std::move(*loaded));
    setFilePath(QString());
    m_doc->undoStack()->resetClean(); // unsaved until the user saves it somewhere
    statusBar()->showMessage(
        tr("Opened what was readable of %1 (%n problem(s) repaired); save it under a new name.",
           nullptr, int(problems.size()))
            .arg(QFileInfo(path).fileName()),
        10000);
    emit recoveredProblems(problems);
    return true;
}
bool MainWindow::save()
{
    if (m_path.isEmpty())
        return saveAs();
    return saveFile(m_path);
}

bool MainWindow::saveAs()
{
    QString path = askSavePath();
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".finbook");
    return saveFile(path);
}

bool MainWindow::saveFile(const QString &path)
{
    settlePoses(); // a saved pose is the converged one
    if (const auto error = model::saveFinbook(*m_doc, path)) {
        reportError(tr("Cannot Save File"), error->message);
        return false;
    }
    m_doc->undoStack()->setClean();
    setFilePath(QFileInfo(path).absoluteFilePath());
    addRecentFile(m_path);
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(m_path)), 4000);
    return true;
}

bool MainWindow::maybeSave()
{
    if (m_doc->undoStack()->isClean())
        return true;
    switch (askToSave()) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::setFilePath(const QString &path)
{
    m_path = path;
    updateTitle();
}

QStringList MainWindow::recentFiles() const
{
    QStringList files = QSettings().value(kRecentKey).toStringList();
    files.erase(std::remove_if(files.begin(), files.end(),
                               [](const QString &f) { return !QFileInfo::exists(f); }),
                files.end());
    return files.mid(0, kMaxRecentFiles);
}

void MainWindow::addRecentFile(const QString &path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    QSettings().setValue(kRecentKey, files.mid(0, kMaxRecentFiles));
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = recentFiles();
    QSettings().setValue(kRecentKey, files); // prune the missing ones for good
    for (int i = 0; i < int(files.size()); ++i) {
        const QString path = files[i];
        QAction *a =
            m_recentMenu->addAction(tr("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        a->setToolTip(QDir::toNativeSeparators(path));
        a->setStatusTip(QDir::toNativeSeparators(path));
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybeSave())
                openFile(path);
        });
    }
    if (files.isEmpty())
        m_recentMenu->addAction(tr("No recent files"))->setEnabled(false);
    m_recentMenu->setEnabled(true);
}

// --- the interactive parts tests override ---------------------------------------------------

bool MainWindow::importMesh(const QString &path)
{
    auto strokes = model::importMeshStrokes(path, m_doc->settings().canvasSize);
    if (!strokes) {
        reportError(tr("Cannot Import Mesh"), strokes.error());
        return false;
    }
    QUndoStack *stack = m_doc->undoStack();
    stack->beginMacro(tr("Import Mesh"));
    auto *add = new model::AddObjectCommand(m_doc, m_state->currentFrameId(), -1,
                                            QFileInfo(path).completeBaseName());
    const model::Id groupId = add->groupId();
    stack->push(add);
    for (const model::StrokeDataPtr &stroke : *strokes)
        stack->push(new model::AddStrokeCommand(m_doc, groupId, stroke));
    stack->endMacro();
    m_state->setCurrentGroupId(groupId);
    return true;
}

namespace {

// The local files a drag carries; empty when it carries none (text, a web link).
QStringList droppedFiles(const QMimeData *mime)
{
    QStringList files;
    if (mime && mime->hasUrls())
        for (const QUrl &url : mime->urls())
            if (url.isLocalFile() && QFileInfo(url.toLocalFile()).isFile())
                files << url.toLocalFile();
    return files;
}

} // namespace

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (!droppedFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QStringList files = droppedFiles(event->mimeData());
    if (files.isEmpty())
        return;
    event->acceptProposedAction();
    for (const QString &path : files) {
        if (QFileInfo(path).suffix().compare(QLatin1String("finbook"), Qt::CaseInsensitive) == 0) {
            if (maybeSave())
                openFile(path);
            return; // the document changed: the other files are not for it
        }
        if (!importPicture(path))
            return;
    }
}

namespace {

// Runs `work` on a worker while a modal progress dialog (no cancel) keeps the window painting;
// returns when it is done.
void runWithProgress(QWidget *parent, const std::function<void()> &work, const QString &text,
                     const QString &title)
{
    QThread *worker = QThread::create(work);
    QProgressDialog progress(text, QString(), 0, 0, parent);
    progress.setWindowTitle(title);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    progress.setCancelButton(nullptr);
    QObject::connect(worker, &QThread::finished, &progress, &QDialog::accept);
    worker->start();
    if (!worker->isFinished())
        progress.exec();
    worker->wait();
    delete worker;
}

} // namespace

bool MainWindow::addPictureObjects(
    const std::function<Expected<std::vector<model::StrokeGroup>, QString>()> &work,
    const QString &reading, const QString &title, const std::function<QString(int)> &done)
{
    // Reading, tracing and meshing a large picture takes a while: on a worker, the window
    // kept painting behind a modal progress dialog.
    auto result =
        std::make_shared<Expected<std::vector<model::StrokeGroup>, QString>>(unexpected(QString()));
    runWithProgress(
        this, [result, work] { *result = work(); }, reading, title);
    if (!*result) {
        reportError(tr("Cannot Import Picture"), result->error());
        return false;
    }
    auto *command =
        new model::ImportPictureCommand(m_doc, m_state->currentFrameId(), -1, std::move(**result));
    if (command->isObsolete()) {
        delete command;
        return false;
    }
    const model::Id top = command->objectIds().back();
    const int count = int(command->objectIds().size());
    m_doc->undoStack()->push(command);
    m_state->setCurrentGroupId(top);
    statusBar()->showMessage(done(count));
    return true;
}

bool MainWindow::askKeyOutBackground(const QString &name, QColor background)
{
    return QMessageBox::question(
               this, tr("Import Picture"),
               tr("\"%1\" stands on a flat background (%2). Make that colour transparent, so "
                  "that the object is only what is drawn on it?")
                   .arg(name, background.name())) == QMessageBox::Yes;
}

bool MainWindow::importPicture(const QString &path)
{
    const QSizeF page(m_doc->settings().canvasSize);
    const QString name = QFileInfo(path).fileName();
    // Read first: a single opaque picture on a flat background (a scan, a drawing exported on
    // white) may have that background keyed out before it is traced and meshed.
    auto layers = std::make_shared<Expected<std::vector<model::PictureLayer>, QString>>(
        unexpected(QString()));
    runWithProgress(
        this, [layers, path] { *layers = model::readPictureLayers(path); },
        tr("Reading \"%1\"...").arg(name), tr("Import Picture"));
    if (!*layers) {
        reportError(tr("Cannot Import Picture"), layers->error());
        return false;
    }
    if ((*layers)->size() == 1)
        if (const auto background = model::flatBackground((*layers)->front().image);
            background && askKeyOutBackground(name, QColor::fromRgb(*background))) {
            model::PictureLayer &layer = (*layers)->front();
            layer.image = model::keyedOut(layer.image, *background, kKeyOutTolerance);
        }
    return addPictureObjects(
        [layers, path, page] { return model::pictureObjectsFromLayers(**layers, path, page); },
        tr("Reading \"%1\"...").arg(name), tr("Import Picture"),
        [name](int count) {
            return tr("Imported \"%1\": %n picture object(s).", nullptr, count).arg(name);
        });
}

bool MainWindow::pastePicture(const QImage &image, std::optional<QPointF> at)
{
    if (image.isNull())
        return false;
    const QPointF centre =
        at ? *at : QRectF(QPointF(0, 0), QSizeF(m_doc->settings().canvasSize)).center();
    const QString name = tr("Pasted picture");
    return addPictureObjects(
        [image, centre, name]() -> Expected<std::vector<model::StrokeGroup>, QString> {
            const QPointF corner(std::round(centre.x() - image.width() / 2.0),
                                 std::round(centre.y() - image.height() / 2.0));
            auto object = model::makePictureObject(model::PictureLayer{name, image, {}}, corner);
            if (!object)
                return unexpected(object.error());
            std::vector<model::StrokeGroup> objects;
            objects.push_back(std::move(*object));
            return objects;
        },
        tr("Reading the pasted picture..."), tr("Paste"),
        [](int) { return tr("Pasted a picture as an object."); });
}

void MainWindow::reportError(const QString &title, const QString &message)
{
    emit errorReported(message);
    QMessageBox box(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box.setDetailedText(m_errorDetails); // empty: no "Show Details..." button
    box.exec();
}

bool MainWindow::askOpenAnyway(const QString &message)
{
    QMessageBox box(QMessageBox::Warning, tr("Damaged File"), message, QMessageBox::Cancel, this);
    box.setInformativeText(tr("Open anyway shows what is still readable as a new, unsaved "
                              "animation; the damaged file is not changed."));
    box.setDetailedText(m_errorDetails);
    QPushButton *open = box.addButton(tr("Open Anyway"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == open;
}

QMessageBox::StandardButton MainWindow::askToSave()
{
    const QString name = m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
    return QMessageBox::warning(
        this, tr("Unsaved Changes"),
        tr("\"%1\" has changes that are not saved. Save them before going on?").arg(name),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
}

QString MainWindow::askOpenPath()
{
    return QFileDialog::getOpenFileName(this, tr("Open Animation"), QFileInfo(m_path).path(),
                                        fileFilter());
}

QString MainWindow::askSavePath()
{
    return QFileDialog::getSaveFileName(this, tr("Save Animation"),
                                        m_path.isEmpty() ? tr("untitled.finbook") : m_path,
                                        fileFilter());
}

} // namespace finbook::ui
