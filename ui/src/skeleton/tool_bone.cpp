#include "../tools/stroke_hit.h"

#include <finbook/deform/skeleton/inverse_kinematics.h>
#include <finbook/geometry/region.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/model/skeleton/skeleton_setup.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/skeleton/skeleton_overlay.h>
#include <finbook/ui/skeleton/tool_bone.h>
#include <finbook/ui/window/editor_state.h>

#include <QMessageBox>
#include <QPainter>

#include <cmath>

namespace finbook::ui {

namespace {
constexpr qreal kJointGrab = 9.0;   // widget px
constexpr qreal kBoneGrab = 7.0;    // widget px
constexpr qreal kObjectGrab = 12.0; // widget px around a stroke

bool editable(const model::StrokeGroup &g)
{
    return g.visible && !g.locked;
}

// The point of segment a–b nearest p: its fraction from a, and how far p is from it.
struct Projection {
    qreal t = 0.0;
    qreal distance = 0.0;
};
Projection project(QPointF p, QPointF a, QPointF b)
{
    const QPointF d = b - a;
    const qreal len2 = QPointF::dotProduct(d, d);
    const qreal t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return {t, QLineF(p, a + t * d).length()};
}

Eigen::Vector2d vec(QPointF p)
{
    return {p.x(), p.y()};
}
} // namespace

BoneTool::BoneTool(model::DeformController *controller, QObject *parent)
    : CanvasTool(parent)
    , m_controller(controller)
{
    m_confirmDiscard = [this] {
        return QMessageBox::question(canvas(), tr("Build Skeleton"),
                                     tr("The object is posed with another deformer. Building a "
                                        "skeleton discards that pose. Build it anyway?")) ==
               QMessageBox::Yes;
    };
}

QIcon BoneTool::icon() const
{
    return QIcon(QStringLiteral(":/icons/tool_bone.svg"));
}

void BoneTool::activate()
{
    if (const model::Frame *f = state()->currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            if (!g.rig.skeleton.empty())
                m_controller->prepare(g.id);
}

void BoneTool::deactivate()
{
    m_drag = {};
    m_hover = {};
}

BoneTool::Hit BoneTool::hitAt(const ToolEvent &event) const
{
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return {};
    const qreal zoom = canvas()->zoom();
    const model::Id current = state()->currentGroupId();
    Hit best;
    qreal bestJoint = kJointGrab / zoom, bestBone = kBoneGrab / zoom;
    for (const model::StrokeGroup &g : f->groups) {
        if (!editable(g) || g.rig.skeleton.empty())
            continue;
        const std::vector<QPointF> joints = g.rig.skeleton.posedJoints();
        const qreal bias = g.id == current ? 0.5 : 1.0; // ties go to the current object
        for (std::size_t j = 0; j < joints.size(); ++j) {
            const qreal d = QLineF(joints[j], event.pos).length() * bias;
            if (d <= bestJoint) {
                bestJoint = d;
                best = {g.id, Part::Joint, int(j)};
            }
        }
        if (best.part == Part::Joint)
            continue;
        for (std::size_t j = 0; j < joints.size(); ++j) {
            const int p = g.rig.skeleton.parent[j];
            if (p < 0)
                continue;
            const qreal d = project(event.pos, joints[std::size_t(p)], joints[j]).distance * bias;
            if (d <= bestBone) {
                bestBone = d;
                best = {g.id, Part::Bone, int(j)};
            }
        }
    }
    return best;
}

model::Id BoneTool::objectAt(const ToolEvent &event) const
{
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return model::kNoId;
    const qreal zoom = canvas()->zoom();
    const auto hit = [&](const model::StrokeGroup &g) {
        for (std::size_t s = 0; s < g.strokes.size(); ++s) {
            const qreal reach = kObjectGrab / zoom + g.strokes[s].data->width / 2;
            for (const model::StrokePoint &p : model::displayedPoints(g, s))
                if (std::hypot(p.x - event.pos.x(), p.y - event.pos.y()) <= reach)
                    return true;
        }
        return false;
    };
    if (const model::StrokeGroup *current = state()->currentGroup();
        current && editable(*current) && hit(*current))
        return current->id;
    for (auto it = f->groups.rbegin(); it != f->groups.rend(); ++it)
        if (editable(*it) && hit(*it))
            return it->id;
    // No line under the cursor: a click inside a shape counts too (the object's shape the
    // skeleton is built from: closed regions and the ink), topmost object first.
    // Each shape is computed once: the current object first, then the others.
    // Closed as the Fill tool closes it: a body filled after raising Close gaps counts.
    const double gap = state()->document()->settings().closeGap;
    const auto inside = [&](const model::StrokeGroup &g) { return insideShape(g, gap, event.pos); };
    const model::StrokeGroup *current = state()->currentGroup();
    if (current && editable(*current) && inside(*current))
        return current->id;
    for (auto it = f->groups.rbegin(); it != f->groups.rend(); ++it)
        if (&*it != current && editable(*it) && inside(*it))
            return it->id;
    return model::kNoId;
}

void BoneTool::build(model::Id groupId)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(groupId);
    if (!g)
        return;
    if (g->isDeformed() && g->rig.isPosed() && !m_confirmDiscard())
        return;
    auto rig = model::buildSkeletonRig(*g, {}, {}, doc->settings().closeGap);
    if (!rig) {
        canvas()->postMessage(rig.error());
        return;
    }
    state()->setCurrentGroupId(groupId);
    doc->undoStack()->beginMacro(tr("Build Skeleton"));
    doc->undoStack()->push(new model::BuildSkeletonCommand(doc, groupId, std::move(*rig)));
    joinIfOverlapping(groupId);
    doc->undoStack()->endMacro();
    m_controller->prepare(groupId);
}

void BoneTool::joinIfOverlapping(model::Id groupId)
{
    model::Document *doc = state()->document();
    const model::GroupLocation at = doc->locateGroup(groupId);
    if (!at.isValid())
        return;
    const auto join = model::proposeJoin(doc->frameAt(at), groupId);
    if (!join)
        return;
    doc->undoStack()->push(new model::JoinPartCommand(doc, groupId, *join));
    if (const model::StrokeGroup *parent = doc->group(join->parent))
        canvas()->postMessage(tr("Joined to %1. Shift-drag its root to join it elsewhere; "
                                 "right-click it to detach it.")
                                  .arg(parent->name));
}

bool BoneTool::startDrag(const Hit &clicked, QPointF at)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(clicked.groupId);
    if (!g)
        return false;
    // The root of a joined part is a joint of its character: dragging it moves the whole
    // character, by the root of the part at its top.
    Hit hit = clicked;
    if (hit.part == Part::Joint && g->rig.skeleton.hangs() &&
        g->rig.skeleton.parent[std::size_t(hit.joint)] < 0) {
        const model::GroupLocation where = doc->locateGroup(hit.groupId);
        const model::Id top = model::characterRoot(doc->frameAt(where), hit.groupId);
        if (const model::StrokeGroup *r = doc->group(top);
            r && r != g && !r->rig.skeleton.empty() && editable(*r)) {
            hit = {top, Part::Joint, r->rig.skeleton.root};
            g = r;
        }
    }
    auto skeleton = model::deformSkeleton(g->rig.skeleton);
    if (!skeleton) {
        canvas()->postMessage(skeleton.error());
        return false;
    }
    m_drag.groupId = hit.groupId;
    m_drag.joint = hit.joint;
    m_drag.skeleton = std::move(*skeleton);
    m_drag.start = model::skeletonPose(g->rig.skeleton);
    m_drag.anchor = g->rig.skeleton.hangs() ? g->rig.skeleton.anchor.motion : model::RigidMotion{};
    m_drag.grabbed = m_drag.anchor.unmap(at);
    const bool root = g->rig.skeleton.parent[std::size_t(hit.joint)] < 0;
    m_drag.kind = hit.part == Part::Bone ? DragKind::Bone : root ? DragKind::Root : DragKind::Joint;
    ++m_dragSerial;
    state()->setCurrentGroupId(clicked.groupId);
    m_controller->prepare(hit.groupId);
    return true;
}

void BoneTool::press(const ToolEvent &event)
{
    m_pressPos = event.pos;
    m_drag = {};
    const Hit hit = hitAt(event);
    if (hit.part != Part::None)
        select(hit);
    if (m_editJoints && hit.part != Part::None) {
        pressEditing(hit, event.pos);
        return;
    }
    if (hit.part == Part::Joint && (event.modifiers & Qt::AltModifier)) {
        toggleLock(hit);
        return;
    }
    if (hit.part == Part::Joint && (event.modifiers & Qt::ShiftModifier)) {
        const model::StrokeGroup *g = state()->document()->group(hit.groupId);
        if (g && g->rig.skeleton.parent[std::size_t(hit.joint)] < 0) {
            state()->setCurrentGroupId(hit.groupId);
            m_drag.groupId = hit.groupId;
            m_drag.joint = hit.joint;
            m_drag.kind = DragKind::Attach;
            m_drag.cursor = event.pos;
            return;
        }
    }
    if (hit.part != Part::None) {
        startDrag(hit, event.pos);
        return;
    }
    const model::Id groupId = objectAt(event);
    if (groupId == model::kNoId) {
        canvas()->postMessage(tr("Click on a visible, unlocked drawing to give it a skeleton."));
        return;
    }
    const model::StrokeGroup *g = state()->document()->group(groupId);
    if (g->rig.skeleton.empty())
        build(groupId);
    else if (m_editJoints)
        canvas()->postMessage(tr("Drag a joint to move it, click a bone to insert a joint; "
                                 "right-click a joint to delete it."));
    else
        canvas()->postMessage(tr("Drag a bone to turn it, a joint to pull it, the root to move "
                                 "the object; press L over a joint to lock it; Shift-drag the "
                                 "root onto another part to join them."));
}

void BoneTool::move(const ToolEvent &event)
{
    if (m_drag.kind == DragKind::None || event.pos == m_pressPos)
        return;
    model::Document *doc = state()->document();
    if (m_drag.kind == DragKind::Attach) {
        m_drag.cursor = event.pos;
        canvas()->update();
        return;
    }
    if (m_drag.kind == DragKind::MoveJoint) {
        push(new model::MoveJointCommand(doc, m_drag.groupId, m_drag.joint,
                                         m_drag.jointRest + (event.pos - m_drag.grabbed),
                                         m_dragSerial));
        return;
    }
    deform::SkeletonPose pose = m_drag.start;
    const Eigen::Vector2d cursor = vec(m_drag.anchor.unmap(event.pos));
    if (m_drag.kind == DragKind::Root) {
        pose.rootOffset += cursor - vec(m_drag.grabbed);
    } else if (m_drag.kind == DragKind::Bone) {
        auto turned = deform::rotateBone(m_drag.skeleton, m_drag.start, m_drag.joint,
                                         vec(m_drag.grabbed), cursor);
        if (!turned)
            return;
        pose = std::move(*turned);
    } else {
        const model::StrokeGroup *g = doc->group(m_drag.groupId);
        if (!g)
            return;
        deform::IkOptions options;
        options.limbBase = g->rig.skeleton.limbBase;
        auto solved = deform::solveIk(m_drag.skeleton, m_drag.start, m_drag.joint, cursor,
                                      g->rig.skeleton.locked, options);
        if (!solved)
            return;
        pose = std::move(solved->pose);
    }
    doc->undoStack()->push(new model::PoseBonesCommand(
        doc, m_drag.groupId, std::vector<double>(pose.angles.begin(), pose.angles.end()),
        QPointF(pose.rootOffset.x(), pose.rootOffset.y()), m_dragSerial));
    canvas()->update();
}

void BoneTool::release(const ToolEvent &event)
{
    if (m_drag.kind == DragKind::Attach) {
        if (event.pos != m_pressPos)
            attach(event.pos);
        m_drag = {};
        canvas()->update();
        return;
    }
    move(event);
    m_drag = {};
}

void BoneTool::attach(QPointF at)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *child = doc->group(m_drag.groupId);
    if (!child)
        return;
    // What lies under the drop, the dragged part left out.
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return;
    const qreal reach = kBoneGrab * 2 / canvas()->zoom();
    const model::StrokeGroup *target = nullptr;
    QPointF rest;
    qreal best = reach;
    for (const model::StrokeGroup &g : f->groups) {
        if (g.id == child->id || !editable(g) || g.rig.skeleton.empty())
            continue;
        const model::SkeletonRig &s = g.rig.skeleton;
        const std::vector<QPointF> shown = s.posedJoints();
        for (std::size_t j = 0; j < shown.size(); ++j) {
            const int p = s.parent[j];
            const auto [t, distance] =
                project(at, p < 0 ? shown[j] : shown[std::size_t(p)], shown[j]);
            if (distance < best) {
                best = distance;
                target = &g;
                // The same place on the rest skeleton, where joins are kept.
                const QPointF ra = p < 0 ? s.joints[j] : s.joints[std::size_t(p)];
                rest = ra + t * (s.joints[j] - ra);
            }
        }
    }
    if (!target) {
        canvas()->postMessage(tr("Drop the root on a bone of another part to join them."));
        return;
    }
    auto *command = new model::JoinPartCommand(
        doc, child->id, model::joinAt(child->rig.skeleton, target->id, rest));
    if (command->isObsolete()) {
        delete command;
        canvas()->postMessage(
            tr("%1 hangs from this part already, so it cannot hang from it in turn.")
                .arg(target->name));
        return;
    }
    push(command);
    m_controller->prepare(child->id);
}

void BoneTool::hover(const ToolEvent &event)
{
    const Hit h = hitAt(event);
    if (h.groupId != m_hover.groupId || h.joint != m_hover.joint || h.part != m_hover.part) {
        m_hover = h;
        canvas()->update();
    }
}

void BoneTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return;
    for (const model::StrokeGroup &g : f->groups) {
        if (!g.visible || g.rig.skeleton.empty())
            continue;
        SkeletonLook look;
        look.current = g.id == state()->currentGroupId();
        look.editing = m_editJoints;
        if (m_selected.groupId == g.id)
            look.selectedJoint = m_selected.joint;
        if (m_drag.groupId == g.id)
            look.highlightJoint = m_drag.joint;
        else if (m_hover.groupId == g.id)
            look.highlightJoint = m_hover.joint;
        paintSkeleton(painter, canvasToWidget, g.rig.skeleton, look);
    }
    if (m_drag.kind == DragKind::Attach) { // the rubber band from the root to the cursor
        const model::StrokeGroup *g = state()->document()->group(m_drag.groupId);
        if (g && m_drag.joint < g->rig.skeleton.jointCount()) {
            const QPointF root = g->rig.skeleton.posedJoints()[std::size_t(m_drag.joint)];
            painter.save();
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(QPen(QColor(40, 150, 90), 2, Qt::DashLine, Qt::RoundCap));
            painter.drawLine(canvasToWidget.map(root), canvasToWidget.map(m_drag.cursor));
            painter.restore();
        }
    }
}

} // namespace finbook::ui
