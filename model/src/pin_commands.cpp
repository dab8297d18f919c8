#include "command_text.h"

#include <finbook/model/pin_commands.h>
#include <finbook/model/render.h>

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
bool finitePoint(QPointF p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y());
}
} // namespace

AddPinCommand::AddPinCommand(Document *doc, Id groupId, QPointF rest, QPointF target,
                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_pin{doc->allocateId(), rest, target}
{
    setText(Command::tr("Add Pin"));
    if (!doc->group(groupId) || !finitePoint(rest) || !finitePoint(target))
        setObsolete(true);
}

void AddPinCommand::redo()
{
    if (isObsolete())
        return;
    std::vector<Pin> pins = m_doc->group(m_groupId)->pins;
    pins.push_back(m_pin);
    m_doc->setPins(m_groupId, std::move(pins));
}

void AddPinCommand::undo()
{
    if (isObsolete())
        return;
    std::vector<Pin> pins = m_doc->group(m_groupId)->pins;
    std::erase_if(pins, [this](const Pin &p) { return p.id == m_pin.id; });
    m_doc->setPins(m_groupId, std::move(pins));
}

RemovePinCommand::RemovePinCommand(Document *doc, Id groupId, Id pinId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_pinId(pinId)
{
    setText(Command::tr("Remove Pin"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || std::none_of(g->pins.begin(), g->pins.end(),
                           [pinId](const Pin &p) { return p.id == pinId; }))
        setObsolete(true);
}

void RemovePinCommand::redo()
{
    if (isObsolete())
        return;
    m_before = m_doc->group(m_groupId)->pins;
    std::vector<Pin> pins = m_before;
    std::erase_if(pins, [this](const Pin &p) { return p.id == m_pinId; });
    m_doc->setPins(m_groupId, std::move(pins));
}

void RemovePinCommand::undo()
{
    if (!isObsolete())
        m_doc->setPins(m_groupId, m_before);
}

MovePinCommand::MovePinCommand(Document *doc, Id groupId, Id pinId, QPointF target, int dragSerial,
                               QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_pinId(pinId)
    , m_serial(dragSerial)
    , m_new(target)
{
    setText(Command::tr("Move Pin"));
    const StrokeGroup *g = doc->group(groupId);
    const auto it = g ? std::find_if(g->pins.begin(), g->pins.end(),
                                     [pinId](const Pin &p) { return p.id == pinId; })
                      : std::vector<Pin>::const_iterator{};
    if (!g || it == g->pins.end() || !finitePoint(target))
        setObsolete(true);
    else
        m_old = it->target;
}

bool MovePinCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const MovePinCommand *>(other);
    if (o->m_groupId != m_groupId || o->m_pinId != m_pinId || o->m_serial != m_serial)
        return false;
    m_new = o->m_new;
    return true;
}

void MovePinCommand::apply(QPointF target)
{
    const StrokeGroup *g = m_doc->group(m_groupId);
    if (isObsolete() || !g)
        return;
    std::vector<Pin> pins = g->pins;
    for (Pin &p : pins)
        if (p.id == m_pinId)
            p.target = target;
    m_doc->setPins(m_groupId, std::move(pins));
}

void MovePinCommand::redo()
{
    apply(m_new);
}
void MovePinCommand::undo()
{
    apply(m_old);
}

ResetDeformationCommand::ResetDeformationCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Reset Deformation"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || std::all_of(g->pins.begin(), g->pins.end(),
                          [](const Pin &p) { return p.rest == p.target; }))
        setObsolete(true);
    else
        m_before = g->pins;
}

void ResetDeformationCommand::redo()
{
    if (isObsolete())
        return;
    std::vector<Pin> pins = m_before;
    for (Pin &p : pins)
        p.target = p.rest;
    m_doc->setPins(m_groupId, std::move(pins));
}

void ResetDeformationCommand::undo()
{
    if (!isObsolete())
        m_doc->setPins(m_groupId, m_before);
}

BakeDeformationCommand::BakeDeformationCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Apply Deformation"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !g->isDeformed() || g->deformed->strokes.size() != g->strokes.size()) {
        setObsolete(true);
        return;
    }
    m_oldStrokes = g->strokes;
    m_oldPins = g->pins;
    m_oldDeformed = g->deformed;
    // The baked strokes keep their ids: they are the same strokes, redrawn.
    m_newStrokes = posedStrokes(*g);
}

void BakeDeformationCommand::redo()
{
    if (isObsolete())
        return;
    m_doc->setPins(m_groupId, {});
    m_doc->setStrokes(m_groupId, m_newStrokes);
}

void BakeDeformationCommand::undo()
{
    if (isObsolete())
        return;
    m_doc->setStrokes(m_groupId, m_oldStrokes);
    m_doc->setPins(m_groupId, m_oldPins);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
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
