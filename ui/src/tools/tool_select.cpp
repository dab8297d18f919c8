#include "stroke_hit.h"

#include <finbook/model/commands.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/tools/tool_select.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

namespace finbook::ui {

namespace {

bool contains(const std::vector<model::Id> &ids, model::Id id)
{
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Calls fn(group, strokeIndex) for every stroke of the current frame listed in `ids`.
void forStrokes(const EditorState &state, const std::vector<model::Id> &ids,
                const std::function<void(const model::StrokeGroup &, std::size_t)> &fn)
{
    if (const model::Frame *f = state.currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            for (std::size_t i = 0; i < g.strokes.size(); ++i)
                if (contains(ids, g.strokes[i].id))
                    fn(g, i);
}

// Calls fn(group) for every picture object of the current frame listed in `ids`.
void forPictures(const EditorState &state, const std::vector<model::Id> &ids,
                 const std::function<void(const model::StrokeGroup &)> &fn)
{
    if (const model::Frame *f = state.currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            if (g.picture && contains(ids, g.id))
                fn(g);
}

// The topmost editable picture object of `frame` whose picture shows at `pos`.
model::Id pictureAt(const model::Frame &frame, QPointF pos)
{
    for (auto it = frame.groups.rbegin(); it != frame.groups.rend(); ++it)
        if (it->picture && isEditable(*it) && model::pictureShowsAt(*it, pos))
            return it->id;
    return model::kNoId;
}

// A stroke of another visible, unlocked layer shown at `pos` (the front layer first), as
// (layer, stroke). In Camera View a layer at a depth is drawn through its own camera, so the
// point is carried from the page the tools work on to that layer's page.
std::optional<std::pair<model::Id, model::Id>> otherLayerStrokeAt(const EditorState &state,
                                                                  const CanvasWidget &canvas,
                                                                  QPointF pos, qreal tolerance)
{
    const model::Document &doc = *state.document();
    const qint64 tick = state.currentTick();
    const QSizeF page(doc.settings().canvasSize);
    const model::CameraState camera = model::cameraAt(doc.camera(), double(tick), page);
    const QTransform toShot = model::cameraTransform(camera, page);
    for (int l = doc.layerCount() - 1; l >= 0; --l) {
        const model::Layer &layer = doc.layerAt(l);
        if (l == doc.currentLayerIndex() || !layer.properties.visible || layer.properties.locked ||
            layer.properties.opacity <= 0.0)
            continue;
        const int cel = model::celAt(layer.cels, tick);
        if (cel < 0)
            continue;
        QPointF at = pos;
        if (canvas.looksThroughCamera() && layer.properties.depth != 0.0) {
            bool invertible = false;
            const QTransform back =
                model::cameraTransform(model::planeCamera(camera, layer.properties.depth, page),
                                       page)
                    .inverted(&invertible);
            if (invertible)
                at = back.map(toShot.map(pos));
        }
        if (const model::Id hit = strokeAt(layer.cels[std::size_t(cel)], at, tolerance);
            hit != model::kNoId)
            return std::pair{layer.id, hit};
    }
    return std::nullopt;
}

} // namespace

SelectTool::SelectTool(QObject *parent)
    : CanvasTool(parent)
{}

QIcon SelectTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("edit-select-lasso"),
                            QIcon(QStringLiteral(":/icons/tool_select.svg")));
}

QRectF SelectTool::selectionBounds() const
{
    QRectF bounds;
    forStrokes(*state(), state()->selectedStrokes(),
               [&](const model::StrokeGroup &g, std::size_t i) {
                   bounds |= strokeBounds(model::displayedPoints(g, i), g.strokes[i].data->width);
               });
    forPictures(*state(), state()->selectedPictures(),
                [&](const model::StrokeGroup &g) { bounds |= model::shownPictureBounds(g); });
    return bounds;
}

SelectTool::BoxHandles SelectTool::boxHandles() const
{
    const QRectF bounds = selectionBounds();
    if (bounds.isNull())
        return {};
    BoxHandles h;
    h.corners = canvas()->canvasToWidget().map(QPolygonF(bounds));
    h.corners.resize(4); // QPolygonF(QRectF) repeats its first corner
    const QPointF topMiddle = (h.corners[0] + h.corners[1]) / 2;
    const QPointF centre = (h.corners[0] + h.corners[2]) / 2;
    QPointF out = topMiddle - centre;
    const qreal length = std::hypot(out.x(), out.y());
    out = length > 1e-9 ? out / length : QPointF(0, -1);
    h.rotate = topMiddle + out * kRotateOffset;
    return h;
}

SelectTool::Handle SelectTool::handleAt(const QPointF &widgetPos) const
{
    const BoxHandles box = boxHandles();
    if (box.corners.isEmpty())
        return Handle::None;
    const auto near = [&](const QPointF &p) {
        return std::abs(p.x() - widgetPos.x()) <= kHandleSize &&
               std::abs(p.y() - widgetPos.y()) <= kHandleSize;
    };
    if (near(box.rotate))
        return Handle::Rotate;
    for (const auto &[corner, handle] :
         {std::pair(0, Handle::TopLeft), std::pair(1, Handle::TopRight),
          std::pair(2, Handle::BottomRight), std::pair(3, Handle::BottomLeft)})
        if (near(box.corners[corner]))
            return handle;
    return box.corners.containsPoint(widgetPos, Qt::OddEvenFill) ? Handle::Inside : Handle::None;
}

QCursor SelectTool::cursorFor(Handle handle) const
{
    switch (handle) {
    case Handle::Inside:
        return Qt::SizeAllCursor;
    case Handle::Rotate:
        return Qt::PointingHandCursor;
    case Handle::TopLeft:
    case Handle::BottomRight:
        return Qt::SizeFDiagCursor;
    case Handle::TopRight:
    case Handle::BottomLeft:
        return Qt::SizeBDiagCursor;
    case Handle::None:
        break;
    }
    return cursor();
}

void SelectTool::press(const ToolEvent &event)
{
    m_start = event.pos;
    m_transform.reset();
    const Handle h = !state()->hasSelection() ? Handle::None : handleAt(event.widgetPos);
    if (h == Handle::None) {
        m_mode = Mode::Lasso;
        m_lasso = QPolygonF{event.pos};
        return;
    }
    m_dragged.clear();
    m_draggedPictures.clear();
    forStrokes(*state(), state()->selectedStrokes(),
               [&](const model::StrokeGroup &g, std::size_t i) {
                   if (isEditable(g))
                       m_dragged.push_back(g.strokes[i].id);
               });
    forPictures(*state(), state()->selectedPictures(), [&](const model::StrokeGroup &g) {
        if (isEditable(g))
            m_draggedPictures.push_back(g.id);
    });
    if (m_dragged.empty() && m_draggedPictures.empty())
        return;
    m_startBounds = selectionBounds();
    const QRectF b = m_startBounds;
    switch (h) {
    case Handle::Inside:
        m_mode = Mode::Move;
        break;
    case Handle::Rotate:
        m_mode = Mode::Rotate;
        break;
    default:
        m_mode = Mode::Scale;
        m_grabbed = h == Handle::TopLeft       ? b.topLeft()
                    : h == Handle::TopRight    ? b.topRight()
                    : h == Handle::BottomRight ? b.bottomRight()
                                               : b.bottomLeft();
        m_anchor = b.center() * 2 - m_grabbed;
        break;
    }
    // The canvas leaves out what is dragged (a picture object's id: its picture); the overlay
    // draws it where the drag takes it.
    std::vector<model::Id> suppressed = m_dragged;
    suppressed.insert(suppressed.end(), m_draggedPictures.begin(), m_draggedPictures.end());
    canvas()->setSuppressedStrokes(std::move(suppressed));
}

void SelectTool::move(const ToolEvent &event)
{
    switch (m_mode) {
    case Mode::Idle:
        return;
    case Mode::Lasso:
        if (QLineF(m_lasso.back(), event.pos).length() * canvas()->zoom() >= 1.0)
            m_lasso << event.pos;
        break;
    default:
        m_transform = dragTransform(event);
        break;
    }
    canvas()->updateCanvasRect();
}

void SelectTool::release(const ToolEvent &event)
{
    const Mode mode = m_mode;
    if (mode == Mode::Lasso) {
        m_lasso << event.pos;
        finishLasso(event);
    } else if (mode != Mode::Idle) {
        m_transform = dragTransform(event);
        commitTransform();
    }
    cancelDrag();
}

void SelectTool::hover(const ToolEvent &event)
{
    const Handle h = !state()->hasSelection() ? Handle::None : handleAt(event.widgetPos);
    canvas()->setCursor(cursorFor(h));
}

QTransform SelectTool::dragTransform(const ToolEvent &event) const
{
    const bool shift = event.modifiers & Qt::ShiftModifier;
    QTransform t;
    if (m_mode == Mode::Move) {
        QPointF d = event.pos - m_start;
        if (shift) // constrain to the dominant axis
            d = std::abs(d.x()) >= std::abs(d.y()) ? QPointF(d.x(), 0) : QPointF(0, d.y());
        t.translate(d.x(), d.y());
    } else if (m_mode == Mode::Rotate) {
        const QPointF c = m_startBounds.center();
        const QPointF a = m_start - c, b = event.pos - c;
        qreal degrees =
            (std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x())) * 180 / std::numbers::pi;
        if (shift)
            degrees = std::round(degrees / 15) * 15;
        t.translate(c.x(), c.y());
        t.rotate(degrees);
        t.translate(-c.x(), -c.y());
    } else if (m_mode == Mode::Scale) {
        const QPointF base = m_grabbed - m_anchor, now = event.pos - m_anchor;
        qreal sx = std::abs(base.x()) > 1e-6 ? now.x() / base.x() : 1.0;
        qreal sy = std::abs(base.y()) > 1e-6 ? now.y() / base.y() : 1.0;
        if (shift) {
            const qreal s = std::max(std::abs(sx), std::abs(sy));
            sx = std::copysign(s, sx);
            sy = std::copysign(s, sy);
        }
        // Never collapse to zero: a flat stroke cannot be scaled back.
        sx = std::abs(sx) < 0.01 ? std::copysign(0.01, sx) : sx;
        sy = std::abs(sy) < 0.01 ? std::copysign(0.01, sy) : sy;
        t.translate(m_anchor.x(), m_anchor.y());
        t.scale(sx, sy);
        t.translate(-m_anchor.x(), -m_anchor.y());
    }
    return t;
}

void SelectTool::finishLasso(const ToolEvent &event)
{
    const bool add = event.modifiers & Qt::ShiftModifier;
    std::vector<model::Id> picked = add ? state()->selectedStrokes() : std::vector<model::Id>{};
    std::vector<model::Id> pictures = add ? state()->selectedPictures() : std::vector<model::Id>{};
    const model::Frame *frame = state()->currentFrame();
    if (!frame) {
        state()->setSelectedStrokes({});
        return;
    }
    const QRectF extent = canvas()->canvasToWidget().mapRect(m_lasso.boundingRect());
    if (extent.width() < 3 && extent.height() < 3) {
        const qreal tolerance = kClickTolerance / canvas()->zoom();
        const model::Id hit = strokeAt(*frame, event.pos, tolerance);
        if (hit == model::kNoId && !add) {
            // Nothing of the current layer there: a click on another layer's drawing makes
            // that layer current (as in Krita and OpenToonz) and picks the stroke.
            if (const auto other = otherLayerStrokeAt(*state(), *canvas(), event.pos, tolerance)) {
                state()->document()->setCurrentLayer(other->first);
                if (state()->document()->locateStroke(other->second).isValid())
                    state()->setSelectedStrokes({other->second});
                return;
            }
        }
        if (hit != model::kNoId && !contains(picked, hit))
            picked.push_back(hit);
        // No line there: a click on a picture picks the picture.
        if (hit == model::kNoId)
            if (const model::Id picture = pictureAt(*frame, event.pos);
                picture != model::kNoId && !contains(pictures, picture))
                pictures.push_back(picture);
        state()->setSelection(std::move(picked), std::move(pictures));
        return;
    }
    for (const model::StrokeGroup &g : frame->groups) {
        if (!isEditable(g))
            continue;
        // A line that Apply Pose split into parts is lassoed whole or not at all, as it was
        // before the pose was applied.
        for (const std::vector<std::size_t> &line : model::linesOfParts(g)) {
            std::vector<model::StrokePoint> points;
            for (std::size_t i : line) {
                const std::vector<model::StrokePoint> &part = model::displayedPoints(g, i);
                points.insert(points.end(), part.begin(), part.end());
            }
            if (fractionInside(points, m_lasso) >= kLassoShare)
                for (std::size_t i : line)
                    if (!contains(picked, g.strokes[i].id))
                        picked.push_back(g.strokes[i].id);
        }
        // Lines of no ink go with the inked lines they join, not with the lasso.
        picked = model::withLinesOfNoInk(g, std::move(picked));
        // A picture whose mesh lies mostly inside the lasso, as a stroke's points.
        if (g.picture && !contains(pictures, g.id)) {
            const Eigen::MatrixX2d V = model::shownPictureVertices(g);
            std::vector<model::StrokePoint> points(std::size_t(V.rows()));
            for (Eigen::Index k = 0; k < V.rows(); ++k)
                points[std::size_t(k)] = {float(V(k, 0)), float(V(k, 1)), 1.0f};
            if (!points.empty() && fractionInside(points, m_lasso) >= kLassoShare)
                pictures.push_back(g.id);
        }
    }
    state()->setSelection(std::move(picked), std::move(pictures));
}

void SelectTool::commitTransform()
{
    if (m_transform.isIdentity() || (m_dragged.empty() && m_draggedPictures.empty()))
        return;
    model::Document *doc = state()->document();
    const qreal widthScale = std::sqrt(std::abs(m_transform.determinant()));
    std::vector<model::Id> ids;
    std::vector<model::Id> groups;
    std::vector<model::StrokeDataPtr> data;
    // A stroke as the drag leaves it: `points` (those shown) mapped, its width scaled; null
    // when a point would leave the finite numbers.
    const auto transformed = [&](const model::StrokeData &stroke,
                                 std::vector<model::StrokePoint> points) -> model::StrokeDataPtr {
        auto moved = std::make_shared<model::StrokeData>(stroke);
        moved->points = std::move(points);
        for (model::StrokePoint &p : moved->points) {
            const QPointF q = m_transform.map(QPointF(p.x, p.y));
            p.x = float(q.x());
            p.y = float(q.y());
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                return nullptr;
        }
        moved->width = float(std::max(0.1, moved->width * widthScale));
        return moved;
    };
    // The transform was made on the strokes as shown, so it applies to the shown points (the
    // pose of a posed object), and such an object's pose becomes its drawing first.
    for (model::Id id : m_dragged) {
        const model::StrokeLocation at = doc->locateStroke(id);
        if (!at.isValid())
            continue;
        const model::StrokeGroup &g = doc->frameAt(at).groups[std::size_t(at.group)];
        model::StrokeDataPtr moved = transformed(*g.strokes[std::size_t(at.stroke)].data,
                                                 model::displayedPoints(g, std::size_t(at.stroke)));
        if (!moved) {
            canvas()->postMessage(tr("The strokes cannot be transformed that far."));
            return;
        }
        ids.push_back(id);
        groups.push_back(g.id);
        data.push_back(std::move(moved));
    }
    const bool onlyPictures = ids.empty();
    const QString text =
        m_mode == Mode::Move     ? (onlyPictures ? tr("Move Picture") : tr("Move Strokes"))
        : m_mode == Mode::Rotate ? (onlyPictures ? tr("Rotate Picture") : tr("Rotate Strokes"))
                                 : (onlyPictures ? tr("Scale Picture") : tr("Scale Strokes"));
    // A cut-out pose bakes a line into its parts (new ids beside the first's): once the pose
    // is the drawing, the parts are moved, each from its own points (those shown).
    // The pictures' new places, checked before anything is changed.
    for (model::Id id : m_draggedPictures) {
        const model::StrokeGroup *g = doc->group(id);
        if (g && g->picture && !model::validPicturePlace(g->picture->place * m_transform)) {
            canvas()->postMessage(tr("The picture cannot be transformed that far."));
            return;
        }
    }
    const std::vector<model::Id> parts = StrokeEditing::beginRestEditOf(doc, text, ids);
    // A posed picture object's pose becomes its picture first (Apply Pose: resampled once);
    // then its picture moves as the drag showed it.
    StrokeEditing::applyPoses(doc, m_draggedPictures);
    for (model::Id id : m_draggedPictures)
        if (const model::StrokeGroup *g = doc->group(id); g && g->picture) {
            doc->undoStack()->push(new model::SetPictureCommand(
                doc, id, model::movedPicture(*g->picture, m_transform), text));
            groups.push_back(id);
        }
    if (parts != ids) {
        data.clear();
        for (model::Id id : parts) {
            const model::StrokeLocation at = doc->locateStroke(id);
            const model::StrokeData &part = *doc->frameAt(at)
                                                 .groups[std::size_t(at.group)]
                                                 .strokes[std::size_t(at.stroke)]
                                                 .data;
            model::StrokeDataPtr moved = transformed(part, part.points);
            data.push_back(moved ? std::move(moved) : std::make_shared<model::StrokeData>(part));
        }
    }
    std::vector<model::Id> fillGroups; // the objects of the moved lines
    for (model::Id id : parts)
        if (const model::StrokeLocation at = doc->locateStroke(id); at.isValid())
            if (const model::Id gid = doc->frameAt(at).groups[std::size_t(at.group)].id;
                !contains(fillGroups, gid))
                fillGroups.push_back(gid);
    const std::vector<model::StrokeGroup> before = StrokeEditing::objectsNow(doc, fillGroups);
    if (!parts.empty())
        doc->undoStack()->push(new model::ReplaceStrokeDataCommand(doc, parts, data, text));
    // A fill region all of whose lines moved moves with them: its seed too, so that it is not
    // left in a neighbouring region that shares a line with it (a whole figure dragged by less
    // than its width lost a small region's colour to its neighbour).
    std::vector<model::Id> sorted = parts;
    std::sort(sorted.begin(), sorted.end());
    for (model::Id gid : fillGroups) {
        std::vector<model::Fill> fills = doc->group(gid)->fills;
        bool changed = false;
        const auto follow = [&](QPointF &seed, const std::vector<model::Id> &strokes) {
            if (strokes.empty() || !std::all_of(strokes.begin(), strokes.end(), [&](model::Id s) {
                    return std::binary_search(sorted.begin(), sorted.end(), s);
                }))
                return;
            seed = m_transform.map(seed);
            changed = true;
        };
        for (model::Fill &fill : fills) {
            follow(fill.seed, fill.strokes);
            for (model::FillPlace &place : fill.more)
                follow(place.seed, place.strokes);
        }
        if (changed)
            doc->undoStack()->push(new model::SetFillsCommand(doc, gid, std::move(fills), text));
    }
    // A head moved off an arm raised behind it (Apply Pose hid the arm's top under the head)
    // shows the arm's top, and the arm keeps its fill.
    StrokeEditing::showUncoveredLines(doc, before);
    StrokeEditing::endRestEdit(*state(), groups); // a shown skeleton follows the moved lines
    if (parts != ids)
        state()->setSelection(parts, state()->selectedPictures());
}

void SelectTool::cancelDrag()
{
    m_mode = Mode::Idle;
    m_lasso.clear();
    m_dragged.clear();
    m_draggedPictures.clear();
    m_transform.reset();
    if (canvas()) {
        canvas()->setSuppressedStrokes({});
        canvas()->updateCanvasRect();
    }
}

void SelectTool::deactivate()
{
    cancelDrag();
}

bool SelectTool::keyPress(QKeyEvent *event)
{
    if (event->key() != Qt::Key_Escape)
        return false;
    if (m_mode != Mode::Idle)
        cancelDrag();
    else if (state()->hasSelection())
        state()->setSelectedStrokes({});
    else
        return false;
    return true;
}

void SelectTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const bool transforming =
        m_mode == Mode::Move || m_mode == Mode::Rotate || m_mode == Mode::Scale;
    if (transforming) {
        painter.save();
        painter.setTransform(m_transform * canvasToWidget, true);
        forPictures(*state(), m_draggedPictures,
                    [&](const model::StrokeGroup &g) { model::paintPicture(painter, g); });
        forStrokes(*state(), m_dragged, [&](const model::StrokeGroup &g, std::size_t i) {
            const model::StrokeData &d = *g.strokes[i].data;
            model::paintStroke(painter, model::displayedPoints(g, i), d.color, d.width);
        });
        painter.restore();
    }
    QPen dark(QColor(20, 20, 20), 1, Qt::DashLine);
    QPen light(QColor(255, 255, 255), 1);
    const auto outline = [&](const QPolygonF &shape, bool closed) {
        painter.setBrush(Qt::NoBrush);
        painter.setPen(light);
        closed ? painter.drawPolygon(shape) : painter.drawPolyline(shape);
        painter.setPen(dark);
        closed ? painter.drawPolygon(shape) : painter.drawPolyline(shape);
    };
    if (m_mode == Mode::Lasso && m_lasso.size() > 1)
        outline(canvasToWidget.map(m_lasso), true);
    const QRectF bounds = transforming ? m_startBounds : selectionBounds();
    if (bounds.isNull() || m_mode == Mode::Lasso)
        return;
    const QPolygonF box = canvasToWidget.map(m_transform.map(QPolygonF(bounds)));
    outline(box, true);
    if (transforming)
        return;
    const BoxHandles handles = boxHandles();
    if (handles.corners.isEmpty())
        return;
    painter.setPen(QPen(QColor(20, 20, 20), 1));
    painter.drawLine((handles.corners[0] + handles.corners[1]) / 2, handles.rotate);
    painter.setBrush(Qt::white);
    painter.drawEllipse(handles.rotate, kHandleSize / 2, kHandleSize / 2);
    for (const QPointF &corner : handles.corners)
        painter.drawRect(QRectF(corner - QPointF(kHandleSize, kHandleSize) / 2,
                                QSizeF(kHandleSize, kHandleSize)));
}

} // namespace finbook::ui
