// Frame → Generate In-betweens…: the dialog with its live preview in the canvas, then one
// InsertInbetweensCommand. The dialog stands beside the page it previews on, or where the
// user last put it.
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/inbetween/inbetween_dialog.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QGuiApplication>
#include <QScreen>
#include <QSettings>

#include <algorithm>

namespace finbook::ui {

namespace {

const QString kPositionKey = QStringLiteral("inbetween/position");

// Where the dialog covers the least of the page: beside it when there is room, else at an
// edge of the window. `size` is the dialog's frame size.
QPoint besidePage(const CanvasWidget *canvas, const QWidget *window, QSize size)
{
    const QSize pageSize = canvas->document()->settings().canvasSize;
    const QPoint topLeft = canvas->mapFromCanvas(QPointF(0, 0)).toPoint();
    const QPoint bottomRight =
        canvas->mapFromCanvas(QPointF(pageSize.width(), pageSize.height())).toPoint();
    // The part of the page the canvas shows, in screen coordinates.
    const QRect page = QRect(topLeft, bottomRight)
                           .normalized()
                           .intersected(canvas->rect())
                           .translated(canvas->mapToGlobal(QPoint(0, 0)));
    const QRect frame = window->frameGeometry();
    QRect room = frame;
    if (const QScreen *screen = window->screen())
        room = room.united(screen->availableGeometry());
    const int margin = 8;
    const int top =
        std::clamp(page.top(), room.top(), std::max(room.top(), room.bottom() - size.height()));
    const QPoint candidates[] = {{page.right() + margin, top},
                                 {page.left() - margin - size.width(), top},
                                 {frame.right() - size.width(), top},
                                 {frame.left(), top}};
    QPoint best = candidates[0];
    qint64 bestCover = -1;
    for (const QPoint &at : candidates) {
        const QRect r(at, size);
        if (!room.contains(r))
            continue;
        const QRect cover = r.intersected(page);
        const qint64 area = cover.isEmpty() ? 0 : qint64(cover.width()) * cover.height();
        if (bestCover < 0 || area < bestCover) {
            best = at;
            bestCover = area;
        }
    }
    return best;
}

} // namespace

void MainWindow::generateInbetweens(model::Id firstKey, model::Id secondKey)
{
    deform::ArapOptions options;
    if (m_deform)
        options.extraPasses = m_deform->controller()->extraPasses(); // preview as it will solve
    InbetweenDialog dialog(
        m_doc, firstKey, secondKey, options,
        [this](std::optional<model::Frame> frame) { m_canvas->setPreviewFrame(std::move(frame)); },
        this);
    dialog.setObjectName(QStringLiteral("inbetweenDialog"));
    dialog.adjustSize();
    QSettings settings;
    const QPoint saved = settings.value(kPositionKey).toPoint();
    // A place on a screen that has gone (or far outside the window) is not used.
    const bool onScreen = settings.contains(kPositionKey) &&
                          (QGuiApplication::screenAt(saved) || frameGeometry().contains(saved));
    dialog.move(onScreen ? saved : besidePage(m_canvas, this, dialog.frameGeometry().size()));
    const int result = dialog.exec();
    settings.setValue(kPositionKey, dialog.pos());
    if (result != QDialog::Accepted)
        return;
    // Drawings carried onto others were made by the dialog off the GUI thread.
    auto *command =
        dialog.plannedFrames()
            ? new model::InsertInbetweensCommand(m_doc, dialog.firstKey(), dialog.secondKey(),
                                                 *dialog.plannedFrames())
            : new model::InsertInbetweensCommand(m_doc, dialog.firstKey(), dialog.secondKey(),
                                                 dialog.count(), dialog.options());
    const bool obsolete = command->isObsolete();
    m_doc->undoStack()->push(command);
    if (!obsolete)
        m_state->setCurrentFrameIndex(m_doc->frameIndex(dialog.firstKey()));
}

} // namespace finbook::ui
