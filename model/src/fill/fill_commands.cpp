// The Fill tool's commands (fill_commands.h).
#include "../command_text.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/shade/same_object.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

SetFillsCommand::SetFillsCommand(Document *doc, Id groupId, std::vector<Fill> fills,
                                 const QString &text, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_new(std::move(fills))
{
    setText(text);
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->fills == m_new)
        setObsolete(true);
    else
        m_old = g->fills;
}

void SetFillsCommand::redo()
{
    if (m_doc->group(m_groupId))
        m_doc->setFills(m_groupId, m_new);
}

void SetFillsCommand::undo()
{
    if (m_doc->group(m_groupId))
        m_doc->setFills(m_groupId, m_old);
}

namespace {
std::unique_ptr<QUndoCommand>
commandFor(Document *doc, Id groupId, std::optional<std::vector<Fill>> fills, const QString &text)
{
    if (!fills)
        return nullptr;
    auto command = std::make_unique<SetFillsCommand>(doc, groupId, std::move(*fills), text);
    if (command->isObsolete())
        return nullptr;
    return command;
}

// An object's first fills are shaded as the object is in the other frames (shade/same_object.h):
// a character filled on a new frame is not flat among its shaded neighbours. Later fills take
// the object's own fills' shading (fill_resolve.h).
std::optional<std::vector<Fill>> shadedAsElsewhere(const Document &doc, const StrokeGroup &group,
                                                   std::optional<std::vector<Fill>> fills)
{
    if (!fills || !group.fills.empty())
        return fills;
    if (const std::optional<FillShading> shading = objectShading(doc, group.id))
        for (Fill &f : *fills)
            f.shading = *shading;
    return fills;
}

struct Target {
    const StrokeGroup *group = nullptr;
    ObjectRegionsPtr regions;
    int face = -1;
};

Target targetAt(Document *doc, Id groupId, QPointF at)
{
    Target t;
    t.group = doc->group(groupId);
    if (!t.group)
        return t;
    t.regions = objectRegions(*t.group, doc->settings().closeGap);
    t.face = displayedFaceAt(*t.regions, *t.group, at);
    return t;
}
} // namespace

std::unique_ptr<QUndoCommand> fillRegionCommand(Document *doc, Id groupId, QPointF at, QRgb color)
{
    const Target t = targetAt(doc, groupId, at);
    if (t.face < 0)
        return nullptr;
    const bool filled = faceFills(*t.regions, t.group->fills)[std::size_t(t.face)] >= 0;
    return commandFor(
        doc, groupId,
        shadedAsElsewhere(*doc, *t.group, fillsWithFace(*t.regions, t.group->fills, t.face, color)),
        filled ? Command::tr("Recolour Fill") : Command::tr("Fill Region"));
}

std::unique_ptr<QUndoCommand> removeFillCommand(Document *doc, Id groupId, QPointF at)
{
    const Target t = targetAt(doc, groupId, at);
    if (t.face < 0)
        return nullptr;
    return commandFor(doc, groupId, fillsWithoutFace(*t.regions, t.group->fills, t.face),
                      Command::tr("Remove Fill"));
}

std::unique_ptr<QUndoCommand> fillAllRegionsCommand(Document *doc, Id groupId, QRgb color)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g)
        return nullptr;
    const ObjectRegionsPtr regions = objectRegions(*g, doc->settings().closeGap);
    return commandFor(doc, groupId,
                      shadedAsElsewhere(*doc, *g, fillsWithAllFaces(*regions, g->fills, color)),
                      Command::tr("Fill All Enclosed Regions"));
}

SetCloseGapCommand::SetCloseGapCommand(Document *doc, double closeGap, int editSerial,
                                       QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_serial(editSerial)
    , m_new(std::isfinite(closeGap) && closeGap >= 0 ? std::min(closeGap, kMaxCloseGap)
                                                     : DocumentSettings().closeGap)
    , m_old(doc->settings().closeGap)
{
    setText(Command::tr("Close Gaps"));
    setObsolete(m_new == m_old);
}

bool SetCloseGapCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const SetCloseGapCommand *>(other);
    if (m_serial < 0 || o->m_serial != m_serial)
        return false;
    m_new = o->m_new;
    setObsolete(m_new == m_old); // back where the session began: the stack drops the step
    return true;
}

void SetCloseGapCommand::redo()
{
    apply(m_new);
}

void SetCloseGapCommand::undo()
{
    apply(m_old);
}

void SetCloseGapCommand::apply(double closeGap)
{
    DocumentSettings settings = m_doc->settings();
    settings.closeGap = closeGap;
    m_doc->setSettings(settings);
}

std::unique_ptr<QUndoCommand> setCloseGapCommand(Document *doc, double closeGap, int editSerial)
{
    auto command = std::make_unique<SetCloseGapCommand>(doc, closeGap, editSerial);
    if (command->isObsolete())
        return nullptr;
    return command;
}

} // namespace finbook::model
