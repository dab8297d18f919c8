// The shading edits (shade/shade_commands.h).
#include "../command_text.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/shade/same_object.h>
#include <finbook/model/shade/shade_commands.h>

#include <algorithm>

namespace finbook::model {

std::unique_ptr<QUndoCommand> shadeFillsCommand(Document *doc, Id groupId,
                                                const FillShading &shading)
{
    const StrokeGroup *group = doc->group(groupId);
    if (!group || group->fills.empty())
        return nullptr;
    const QString text =
        shading.shaded() ? Command::tr("Shade Fills") : Command::tr("Unshade Fills");
    // One step over every frame: set on one frame only, playback flickered between shaded and
    // flat frames of one character.
    auto command = std::make_unique<QUndoCommand>(text);
    for (const Id id : sameObjectInFrames(*doc, groupId)) {
        const std::vector<Fill> &old = doc->group(id)->fills;
        if (std::all_of(old.begin(), old.end(),
                        [&](const Fill &f) { return f.shading == shading; }))
            continue; // no fills, or already so: an obsolete child would undo to no fills
        std::vector<Fill> fills = old;
        for (Fill &f : fills)
            f.shading = shading;
        new SetFillsCommand(doc, id, std::move(fills), text, command.get()); // owned by `command`
    }
    if (command->childCount() > 0)
        return command;
    return nullptr;
}

std::unique_ptr<QUndoCommand> setLightCommand(Document *doc, double azimuth, double elevation)
{
    DocumentSettings settings = doc->settings();
    settings.lightAzimuth = azimuth;
    settings.lightElevation = elevation;
    auto command = std::make_unique<ChangeSettingsCommand>(doc, settings);
    if (command->isObsolete())
        return nullptr;
    command->setText(Command::tr("Move Light"));
    return command;
}

} // namespace finbook::model
