#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/skeleton/skeleton_overlay.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>

namespace finbook::ui {

void paintSkeleton(QPainter &painter, const QTransform &canvasToWidget,
                   const model::SkeletonRig &skeleton, const SkeletonLook &look)
{
    if (skeleton.empty() || !skeleton.isValid())
        return;
    const std::vector<QPointF> joints = skeleton.posedJoints();
    const qreal scale = std::sqrt(std::abs(canvasToWidget.determinant()));
    const QColor bone = look.current ? QColor(240, 140, 20) : QColor(130, 130, 130);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const bool hangs = skeleton.hangs();
    if (hangs) { // the join: a dashed link from the part's root to where it hangs
        const QPointF root = canvasToWidget.map(joints[std::size_t(skeleton.root)]);
        const QPointF at = canvasToWidget.map(skeleton.anchor.motion.map(skeleton.join.parentAt));
        painter.setPen(QPen(QColor(255, 255, 255, 200), 4, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(root, at);
        painter.setPen(QPen(QColor(40, 150, 90), 2, Qt::DashLine, Qt::RoundCap));
        painter.drawLine(root, at);
        painter.setBrush(QColor(40, 150, 90));
        painter.setPen(QPen(Qt::white, 1.2));
        painter.drawEllipse(at, 3.5, 3.5);
    }
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const int p = skeleton.parent[j];
        if (p < 0)
            continue;
        const QLineF line(canvasToWidget.map(joints[std::size_t(p)]),
                          canvasToWidget.map(joints[j]));
        const bool hot = int(j) == look.highlightJoint || int(j) == look.selectedJoint;
        painter.setPen(QPen(QColor(255, 255, 255, 200), hot ? 7 : 5, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(line);
        painter.setPen(QPen(hot ? bone.darker(130) : bone, hot ? 4 : 2.5,
                            look.editing ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(line);
    }
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const QPointF at = canvasToWidget.map(joints[j]);
        const qreal r = std::max(3.0, skeleton.radius[j] * scale);
        QColor ring = bone;
        ring.setAlpha(look.current ? 170 : 110);
        painter.setPen(QPen(ring, int(j) == look.highlightJoint ? 2.5 : 1.2));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(at, r, r);
        const bool locked = skeleton.isLocked(int(j));
        if (int(j) == look.selectedJoint) {
            painter.setPen(QPen(QColor(30, 110, 230), 2.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(at, 9, 9);
        }
        if (locked) { // a second, red ring: the joint is held in place
            painter.setPen(QPen(QColor(200, 30, 30), 2.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(at, 7, 7);
        }
        painter.setPen(QPen(Qt::white, 1.5));
        // A limb's base (where it leaves the body, and where it turns when its tip is
        // dragged): a blue dot.
        painter.setBrush(locked                        ? QColor(200, 30, 30)
                         : skeleton.isLimbBase(int(j)) ? QColor(40, 110, 220)
                                                       : bone.darker(120));
        if (int(j) == skeleton.root && hangs) { // a joined part's root: a green diamond
            painter.setBrush(locked ? QColor(200, 30, 30) : QColor(40, 150, 90));
            const QPointF d[4] = {at + QPointF(0, -6), at + QPointF(6, 0), at + QPointF(0, 6),
                                  at + QPointF(-6, 0)};
            painter.drawPolygon(d, 4);
        } else if (int(j) == skeleton.root) // a character's root: a square
            painter.drawRect(QRectF(at - QPointF(5, 5), QSizeF(10, 10)));
        else
            painter.drawEllipse(at, 4, 4);
    }
    painter.restore();
}

SkeletonOverlay::SkeletonOverlay(EditorState *state, CanvasWidget *canvas)
    : QObject(canvas)
    , m_state(state)
    , m_canvas(canvas)
{
    connect(m_state->document(), &model::Document::constraintsChanged, this, [this] {
        if (m_shown)
            m_canvas->update();
    });
}

void SkeletonOverlay::setShown(bool shown)
{
    if (shown == m_shown)
        return;
    m_shown = shown;
    m_state->setShowSkeleton(shown);
    m_canvas->update();
    emit shownChanged(shown);
}

void SkeletonOverlay::paint(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *f = m_canvas->shownFrame();
    if (!m_shown || !f)
        return;
    for (const model::StrokeGroup &g : f->groups)
        if (g.visible && !g.rig.skeleton.empty())
            paintSkeleton(painter, canvasToWidget, g.rig.skeleton,
                          {g.id == m_state->currentGroupId(), -1, -1, false});
}

} // namespace finbook::ui
