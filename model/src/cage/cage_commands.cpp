#include "../command_text.h"

#include <finbook/model/cage/cage_commands.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
bool allFinite(const std::vector<QPointF> &points)
{
    return std::all_of(points.begin(), points.end(),
                       [](QPointF p) { return std::isfinite(p.x()) && std::isfinite(p.y()); });
}

Rig cageRig(std::vector<QPointF> corners)
{
    Rig rig;
    rig.cage.posed = corners;
    rig.cage.rest = std::move(corners);
    return rig;
}

Rig withCage(CageRig cage)
{
    Rig rig;
    rig.cage = std::move(cage);
    return rig;
}

Rig withPosedCorners(const Document *doc, Id groupId, std::vector<QPointF> posed)
{
    const StrokeGroup *g = doc->group(groupId);
    Rig rig = g ? g->rig : Rig{};
    rig.cage.posed = std::move(posed);
    return rig;
}

bool hasCage(const Document *doc, Id groupId)
{
    const StrokeGroup *g = doc->group(groupId);
    return g && g->rig.kind() == RigKind::Cage;
}
} // namespace

PlaceCageCommand::PlaceCageCommand(Document *doc, Id groupId, std::vector<QPointF> corners,
                                   QUndoCommand *parent)
    : SetRigCommand(doc, groupId, cageRig(corners), Command::tr("Place Cage"), parent)
{
    if (corners.size() < 3 || !allFinite(corners))
        setObsolete(true);
}

EditCageCommand::EditCageCommand(Document *doc, Id groupId, CageRig cage, QUndoCommand *parent)
    : SetRigCommand(doc, groupId, withCage(cage), Command::tr("Edit Cage"), parent)
{
    if (!hasCage(doc, groupId) || cage.rest.size() < 3 || cage.posed.size() != cage.rest.size() ||
        !allFinite(cage.rest) || !allFinite(cage.posed))
        setObsolete(true);
}

MoveCageCornersCommand::MoveCageCornersCommand(Document *doc, Id groupId,
                                               std::vector<QPointF> posed, int dragSerial,
                                               QUndoCommand *parent)
    : PoseRigCommand(doc, groupId, withPosedCorners(doc, groupId, posed), dragSerial,
                     Command::tr("Move Cage Corners"), parent)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!hasCage(doc, groupId) || posed.size() != g->rig.cage.rest.size() || !allFinite(posed))
        setObsolete(true);
}

RemoveRigCommand::RemoveRigCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : SetRigCommand(doc, groupId, Rig{}, Command::tr("Remove Rig"), parent)
{}

} // namespace finbook::model
