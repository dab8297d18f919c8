// CameraTool: a drag turned into one undo step that sets the camera key at the current tick.
#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/document.h>
#include <finbook/ui/camera/bezier_editor.h>
#include <finbook/ui/camera/tool_camera.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QActionGroup>
#include <QKeyEvent>
#include <QMenu>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace finbook::ui {

namespace {

double angleOf(QPointF v)
{
    return std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi;
}

// The most centres the path samples: a long shot's path stays cheap to draw.
constexpr qint64 kMostPathSamples = 4000;

} // namespace

QIcon CameraTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("camera-video"),
                            QIcon(QStringLiteral(":/icons/tool_camera.svg")));
}

QCursor CameraTool::cursor() const
{
    return m_dragging ? Qt::ClosedHandCursor : Qt::OpenHandCursor;
}

qint64 CameraTool::currentTick() const
{
    return state()->currentTick();
}

model::CameraState CameraTool::currentState() const
{
    const model::Document &doc = *state()->document();
    return model::cameraAt(doc.camera(), double(currentTick()), QSizeF(doc.settings().canvasSize));
}

void CameraTool::press(const ToolEvent &event)
{
    m_start = currentState();
    m_startView = canvas()->canvasToWidget();
    m_pressWidget = event.widgetPos;
    m_edit = event.modifiers & Qt::ShiftModifier     ? Edit::Zoom
             : event.modifiers & Qt::ControlModifier ? Edit::Turn
                                                     : Edit::Move;
    ++m_dragSerial;
    m_dragging = true;
    canvas()->setCursor(cursor());
}

void CameraTool::move(const ToolEvent &event)
{
    if (!m_dragging)
        return;
    bool invertible = false;
    const QTransform toPage = m_startView.inverted(&invertible);
    if (!invertible)
        return;
    // Page points under the press and under the pointer, seen as the drag began: in Camera
    // View the view moves with the camera, and measuring in it would chase the pointer.
    const QPointF from = toPage.map(m_pressWidget);
    const QPointF to = toPage.map(event.widgetPos);
    // Over the page the frame follows the pointer; in Camera View the picture does (the
    // camera goes the other way).
    const double sign = state()->cameraView() ? -1.0 : 1.0;
    model::CameraState next = m_start;
    const QPointF c = m_start.center;
    switch (m_edit) {
    case Edit::Move:
        next.center = m_start.center + sign * (to - from);
        break;
    case Edit::Zoom: {
        const double a = QLineF(c, from).length(), b = QLineF(c, to).length();
        if (a < 1e-6 || b < 1e-6)
            return;
        next.zoom = std::clamp(m_start.zoom * std::pow(b / a, -sign), model::kMinCameraZoom,
                               model::kMaxCameraZoom);
        break;
    }
    case Edit::Turn:
        if (QLineF(c, from).length() < 1e-6 || QLineF(c, to).length() < 1e-6)
            return;
        next.rotation = std::clamp(
            m_start.rotation - sign * std::remainder(angleOf(to - c) - angleOf(from - c), 360.0),
            -model::kMaxCameraTurn, model::kMaxCameraTurn);
        break;
    }
    setKey(next, m_dragSerial);
}

void CameraTool::release(const ToolEvent &)
{
    m_dragging = false;
    canvas()->setCursor(cursor());
}

void CameraTool::deactivate()
{
    m_dragging = false;
}

void CameraTool::setKey(const model::CameraState &camera, qint64 mergeKey)
{
    model::Document *doc = state()->document();
    const qint64 tick = currentTick();
    const int at = doc->camera().keyAt(tick);
    model::CameraKey key = at >= 0 ? doc->camera().keys[std::size_t(at)] : model::CameraKey{};
    key.tick = tick;
    key.center = camera.center;
    key.zoom = camera.zoom;
    key.rotation = camera.rotation;
    if (auto command = model::setCameraKeyCommand(doc, key, mergeKey))
        doc->undoStack()->push(command.release());
    canvas()->update();
}

void CameraTool::setEasing(model::CameraEasing easing)
{
    model::Document *doc = state()->document();
    const int at = doc->camera().keyAt(currentTick());
    model::CameraKey key;
    if (at >= 0) {
        key = doc->camera().keys[std::size_t(at)];
    } else { // a key where the camera is now, easing from here
        const model::CameraState now = currentState();
        key.tick = currentTick();
        key.center = now.center;
        key.zoom = now.zoom;
        key.rotation = now.rotation;
    }
    key.easing = easing;
    if (auto command = model::setCameraKeyCommand(doc, key))
        doc->undoStack()->push(command.release());
}

void CameraTool::editBezier()
{
    model::Document *doc = state()->document();
    const int at = doc->camera().keyAt(currentTick());
    model::CameraKey key = at >= 0 ? doc->camera().keys[std::size_t(at)] : model::CameraKey{};
    BezierEditorDialog dialog(key.control1, key.control2, canvas());
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (at < 0) {
        const model::CameraState now = currentState();
        key.tick = currentTick();
        key.center = now.center;
        key.zoom = now.zoom;
        key.rotation = now.rotation;
    }
    key.easing = model::CameraEasing::Bezier;
    key.control1 = dialog.control1();
    key.control2 = dialog.control2();
    if (auto command = model::setCameraKeyCommand(doc, key))
        doc->undoStack()->push(command.release());
}

void CameraTool::deleteKey()
{
    model::Document *doc = state()->document();
    if (auto command = model::removeCameraKeyCommand(doc, currentTick()))
        doc->undoStack()->push(command.release());
    canvas()->update();
}

void CameraTool::secondaryClick(const ToolEvent &event)
{
    const model::Document *doc = state()->document();
    const int at = doc->camera().keyAt(currentTick());
    const model::CameraEasing current =
        at >= 0 ? doc->camera().keys[std::size_t(at)].easing : model::CameraEasing::Linear;
    QMenu menu(canvas());
    QMenu *easing = menu.addMenu(tr("Easing to the Next Key"));
    easing->setObjectName(QStringLiteral("camera.easing"));
    auto *group = new QActionGroup(easing);
    const std::pair<model::CameraEasing, QString> kinds[] = {
        {model::CameraEasing::Linear, tr("Linear")},
        {model::CameraEasing::EaseIn, tr("Ease In")},
        {model::CameraEasing::EaseOut, tr("Ease Out")},
        {model::CameraEasing::EaseInOut, tr("Ease In and Out")},
        {model::CameraEasing::Hold, tr("Hold, Then Cut")},
    };
    std::vector<std::pair<QAction *, model::CameraEasing>> easings;
    for (const auto &[kind, text] : kinds) {
        QAction *a = easing->addAction(text);
        a->setObjectName(QStringLiteral("camera.easing.%1").arg(int(kind)));
        a->setCheckable(true);
        a->setChecked(at >= 0 && kind == current);
        group->addAction(a);
        easings.emplace_back(a, kind);
    }
    QAction *bezier = easing->addAction(tr("Bézier Curve..."));
    bezier->setObjectName(QStringLiteral("camera.easing.bezier"));
    bezier->setCheckable(true);
    bezier->setChecked(at >= 0 && current == model::CameraEasing::Bezier);
    group->addAction(bezier);
    menu.addSeparator();
    QAction *remove = menu.addAction(tr("Delete Camera Key"));
    remove->setObjectName(QStringLiteral("camera.deleteKey"));
    remove->setEnabled(at >= 0);
    QAction *reset = menu.addAction(tr("Reset Camera"));
    reset->setObjectName(QStringLiteral("camera.reset"));
    const QPoint global = canvas()->mapToGlobal(event.widgetPos.toPoint());
    QAction *chosen = m_menuExec ? m_menuExec(menu, global) : menu.exec(global);
    if (!chosen || !chosen->isEnabled())
        return;
    for (const auto &[action, kind] : easings)
        if (chosen == action)
            setEasing(kind);
    if (chosen == bezier)
        editBezier();
    else if (chosen == remove)
        deleteKey();
    else if (chosen == reset)
        setKey(model::restCamera(QSizeF(doc->settings().canvasSize)), -1);
}

bool CameraTool::claimsKey(const QKeyEvent &event) const
{
    return (event.key() == Qt::Key_Delete || event.key() == Qt::Key_Backspace) &&
           event.modifiers() == Qt::NoModifier &&
           state()->document()->camera().keyAt(currentTick()) >= 0;
}

bool CameraTool::keyPress(QKeyEvent *event)
{
    if (!claimsKey(*event))
        return false;
    deleteKey();
    return true;
}

void CameraTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Document &doc = *state()->document();
    const model::CameraTrack &track = doc.camera();
    const QSizeF page(doc.settings().canvasSize);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const QColor colour(230, 120, 20);
    if (!track.isEmpty()) {
        // The path of the frame's centre, tick by tick, and the frame of each key, faint.
        const qint64 first = track.keys.front().tick, last = track.keys.back().tick;
        const qint64 step = std::max<qint64>(1, (last - first) / kMostPathSamples);
        QPolygonF path;
        for (qint64 t = first; t <= last; t += step)
            path << canvasToWidget.map(model::cameraAt(track, double(t), page).center);
        path << canvasToWidget.map(track.keys.back().center);
        QPen line(colour, 1.5);
        line.setCosmetic(true);
        painter.setPen(line);
        painter.drawPolyline(path);
        QPen faint(QColor(colour.red(), colour.green(), colour.blue(), 90), 1, Qt::DashLine);
        faint.setCosmetic(true);
        for (const model::CameraKey &k : track.keys) {
            painter.setPen(faint);
            painter.setBrush(Qt::NoBrush);
            painter.drawPolygon(
                canvasToWidget.map(model::cameraFrame({k.center, k.zoom, k.rotation}, page)));
            painter.setPen(QPen(Qt::white, 1));
            painter.setBrush(k.tick == currentTick() ? colour : colour.darker(150));
            painter.drawEllipse(canvasToWidget.map(k.center), 4.5, 4.5);
        }
    }
    // The frame now, with a cross at its centre.
    const model::CameraState now = currentState();
    QPen bold(colour, 2);
    bold.setCosmetic(true);
    painter.setPen(bold);
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(canvasToWidget.map(model::cameraFrame(now, page)));
    const QPointF c = canvasToWidget.map(now.center);
    painter.drawLine(c - QPointF(6, 0), c + QPointF(6, 0));
    painter.drawLine(c - QPointF(0, 6), c + QPointF(0, 6));
    painter.restore();
}

} // namespace finbook::ui
