// MainWindow: how the toolbars are laid out. Tools stand in a vertical bar on the left (as in
// Krita and Pencil2D), with room for more tools; the top row holds files and undo (icons
// only, so nothing moves when the undo text changes), the pen and the deformation. At
// 1280 px nothing an animator needs falls into a toolbar's overflow menu.
#include <finbook/ui/window/main_window.h>

#include <QAction>
#include <QGuiApplication>
#include <QIcon>
#include <QScreen>
#include <QToolBar>

namespace finbook::ui {

namespace {
QIcon themedIcon(const QString &theme, const QString &file)
{
    return QIcon::fromTheme(theme, QIcon(QStringLiteral(":/icons/%1.svg").arg(file)));
}
} // namespace

void MainWindow::arrangeToolBars()
{
    const struct {
        const char *action;
        const char *theme;
        const char *file;
    } icons[] = {
        {"file.new", "document-new", "file_new"},    {"file.open", "document-open", "file_open"},
        {"file.save", "document-save", "file_save"}, {"edit.undo", "edit-undo", "edit_undo"},
        {"edit.redo", "edit-redo", "edit_redo"},
    };
    for (const auto &icon : icons)
        if (QAction *a = action(QString::fromLatin1(icon.action)))
            a->setIcon(themedIcon(QString::fromLatin1(icon.theme), QString::fromLatin1(icon.file)));
    // QUndoStack renames its actions "Undo Draw Stroke" and so on: that text stays in the menu
    // and the tooltip, while the button keeps its icon and one short name.
    if (QAction *undo = action(QStringLiteral("edit.undo")))
        undo->setIconText(tr("Undo"));
    if (QAction *redo = action(QStringLiteral("edit.redo")))
        redo->setIconText(tr("Redo"));
    // Short names on the Deform toolbar leave room for the cage and skeleton; the menu and
    // the tooltip keep the full ones.
    if (QAction *apply = action(QStringLiteral("deform.apply")))
        apply->setIconText(tr("Apply Pose"));
    if (QAction *unpin = action(QStringLiteral("deform.removePins")))
        unpin->setIconText(tr("Remove Rig"));
    if (QAction *reset = action(QStringLiteral("deform.reset")))
        reset->setIconText(tr("Reset"));
    if (QAction *shape = action(QStringLiteral("cage.editShape")))
        shape->setIconText(tr("Shape"));
    m_fileBar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    m_fileBar->setIconSize(QSize(22, 22));
    m_toolsBar->setOrientation(Qt::Vertical);
}

QSize MainWindow::defaultSize() const
{
    // Fits a 1280×800 screen (or a smaller one) with room for the title bar.
    QSize size(1280, 840);
    if (const QScreen *s = screen() ? screen() : QGuiApplication::primaryScreen())
        size = size.boundedTo(s->availableGeometry().size() - QSize(0, 40));
    return size;
}

} // namespace finbook::ui
