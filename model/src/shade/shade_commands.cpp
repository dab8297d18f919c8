// The shading edits (shade/shade_commands.h).
#include "../command_text.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/shade/shade_commands.h>

namespace finbook::model {

std::unique_ptr<QUndoCommand> shadeFillsCommand(Document *doc, Id groupId,
                                                const FillShading &shading)
{
    const StrokeGroup *group = doc->group(groupId);
    if (!group || group->fills.empty())
        return nullptr;
    std::vector<Fill> fills = group->fills;
    for (Fill &f : fills)
        f.shading = shading;
    auto command = std::make_unique<SetFillsCommand>(
        doc, groupId, std::move(fills),
        shading.shaded() ? Command::tr("Shade Fills") : Command::tr("Unshade Fills"));
    if (command->isObsolete())
        return nullptr;
    return command;
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
