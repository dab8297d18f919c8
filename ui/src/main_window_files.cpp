// MainWindow: new, open, save, export and the recent-files list.
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>
#include <finbook/ui/editor_state.h>
#include <finbook/ui/main_window.h>

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMenu>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>

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
    if (const auto error = model::openFinbook(*m_doc, path)) {
        reportError(tr("Cannot Open File"), error->message);
        return false;
    }
    setFilePath(QFileInfo(path).absoluteFilePath());
    addRecentFile(m_path);
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

void MainWindow::exportFrames()
{
    const QString folder = askExportFolder();
    if (folder.isEmpty())
        return;
    const model::DocumentSettings &settings = m_doc->settings();
    QProgressDialog progress(tr("Exporting frames..."), tr("Cancel"), 0, m_doc->frameCount(), this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    for (int i = 0; i < m_doc->frameCount() && !progress.wasCanceled(); ++i) {
        progress.setValue(i);
        const QImage image = model::renderFrame(m_doc->frameAt(i), settings, settings.canvasSize);
        const QString file = QDir(folder).filePath(
            QStringLiteral("frame_%1.png").arg(i + 1, 4, 10, QLatin1Char('0')));
        if (!image.save(file, "PNG")) {
            reportError(tr("Cannot Export Frames"),
                        tr("Cannot write %1. Check that the folder is writable and the disk is "
                           "not full, then export again.")
                            .arg(QDir::toNativeSeparators(file)));
            return;
        }
    }
    progress.setValue(m_doc->frameCount());
    statusBar()->showMessage(tr("Exported %n frame(s) to %1", nullptr, m_doc->frameCount())
                                 .arg(QDir::toNativeSeparators(folder)),
                             5000);
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

void MainWindow::reportError(const QString &title, const QString &message)
{
    emit errorReported(message);
    QMessageBox::warning(this, title, message);
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

QString MainWindow::askExportFolder()
{
    return QFileDialog::getExistingDirectory(this, tr("Export Frames to Folder"),
                                             QFileInfo(m_path).path());
}

} // namespace finbook::ui
