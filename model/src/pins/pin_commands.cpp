#include "../command_text.h"

#include <finbook/model/pins/pin_commands.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
bool finitePoint(QPointF p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// The object's rig with a pin added; a cage gives way to pins.
Rig withPin(const Document *doc, Id groupId, const Pin &pin)
{
    const StrokeGroup *g = doc->group(groupId);
    Rig rig;
    if (g && g->rig.kind() == RigKind::Pins)
        rig.pins = g->rig.pins;
    rig.pins.push_back(pin);
    return rig;
}

Rig withoutPin(const Document *doc, Id groupId, Id pinId)
{
    const StrokeGroup *g = doc->group(groupId);
    Rig rig = g ? g->rig : Rig{};
    std::erase_if(rig.pins, [pinId](const Pin &p) { return p.id == pinId; });
    return rig;
}

Rig withPinTarget(const Document *doc, Id groupId, Id pinId, QPointF target)
{
    const StrokeGroup *g = doc->group(groupId);
    Rig rig = g ? g->rig : Rig{};
    for (Pin &p : rig.pins)
        if (p.id == pinId)
            p.target = target;
    return rig;
}

bool hasPin(const Document *doc, Id groupId, Id pinId)
{
    const StrokeGroup *g = doc->group(groupId);
    return g && std::any_of(g->rig.pins.begin(), g->rig.pins.end(),
                            [pinId](const Pin &p) { return p.id == pinId; });
}
} // namespace

AddPinCommand::AddPinCommand(Document *doc, Id groupId, QPointF rest, QPointF target,
                             QUndoCommand *parent)
    : SetRigCommand(doc, groupId, withPin(doc, groupId, Pin{doc->allocateId(), rest, target}),
                    Command::tr("Add Pin"), parent)
    , m_pinId(m_new.pins.back().id)
{
    if (!finitePoint(rest) || !finitePoint(target))
        setObsolete(true);
}

RemovePinCommand::RemovePinCommand(Document *doc, Id groupId, Id pinId, QUndoCommand *parent)
    : SetRigCommand(doc, groupId, withoutPin(doc, groupId, pinId), Command::tr("Remove Pin"),
                    parent)
{
    if (!hasPin(doc, groupId, pinId))
        setObsolete(true);
}

MovePinCommand::MovePinCommand(Document *doc, Id groupId, Id pinId, QPointF target, int dragSerial,
                               QUndoCommand *parent)
    : PoseRigCommand(doc, groupId, withPinTarget(doc, groupId, pinId, target), dragSerial,
                     Command::tr("Move Pin"), parent)
{
    if (!hasPin(doc, groupId, pinId) || !finitePoint(target))
        setObsolete(true);
}

SetMeshDensityCommand::SetMeshDensityCommand(Document *doc, Id groupId, double density,
                                             int editSerial, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_serial(editSerial)
    , m_new(std::isfinite(density) ? std::clamp(density, kMinMeshDensity, kMaxMeshDensity)
                                   : kDefaultMeshDensity)
{
    setText(Command::tr("Change Mesh Density"));
    if (const StrokeGroup *g = doc->group(groupId); g && g->meshDensity != m_new)
        m_old = g->meshDensity;
    else
        setObsolete(true);
}

bool SetMeshDensityCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const SetMeshDensityCommand *>(other);
    if (o->m_groupId != m_groupId || o->m_serial != m_serial)
        return false;
    m_new = o->m_new;
    return true;
}

void SetMeshDensityCommand::redo()
{
    if (!isObsolete())
        m_doc->setGroupMeshDensity(m_groupId, m_new);
}

void SetMeshDensityCommand::undo()
{
    if (!isObsolete())
        m_doc->setGroupMeshDensity(m_groupId, m_old);
}

} // namespace finbook::model
