// The same object across frames (shade/same_object.h).
#include <finbook/model/shade/same_object.h>

#include <cstdlib>

namespace finbook::model {

namespace {
// Index of the `rank`-th object named `name` in `frame` (back to front), -1 when fewer.
int namesake(const Frame &frame, const QString &name, int rank)
{
    for (std::size_t i = 0; i < frame.groups.size(); ++i)
        if (frame.groups[i].name == name && rank-- == 0)
            return int(i);
    return -1;
}

// The object's place in each frame that holds it, in frame order.
std::vector<GroupLocation> namesakes(const Document &doc, const GroupLocation &at)
{
    if (!at.isValid())
        return {};
    const Frame &own = doc.frameAt(at);
    const QString &name = own.groups[std::size_t(at.group)].name;
    int rank = 0;
    for (int i = 0; i < at.group; ++i)
        if (own.groups[std::size_t(i)].name == name)
            ++rank;
    // Its layer's cels: another layer's namesake is another character.
    const std::vector<Frame> &cels = doc.layerAt(at.layer).cels;
    std::vector<GroupLocation> places;
    for (int f = 0; f < int(cels.size()); ++f) {
        const int g = f == at.frame ? at.group : namesake(cels[std::size_t(f)], name, rank);
        if (g >= 0)
            places.push_back({f, g, at.layer});
    }
    return places;
}
} // namespace

std::vector<Id> sameObjectInFrames(const Document &doc, Id groupId)
{
    std::vector<Id> ids;
    for (const GroupLocation &place : namesakes(doc, doc.locateGroup(groupId)))
        ids.push_back(doc.frameAt(place).groups[std::size_t(place.group)].id);
    return ids;
}

std::optional<FillShading> objectShading(const Document &doc, Id groupId)
{
    const GroupLocation at = doc.locateGroup(groupId);
    std::optional<FillShading> best;
    int bestDistance = 0;
    for (const GroupLocation &place : namesakes(doc, at)) {
        const StrokeGroup &g = doc.frameAt(place).groups[std::size_t(place.group)];
        if (g.fills.empty())
            continue;
        const int distance = std::abs(place.frame - at.frame);
        if (!best || distance < bestDistance) {
            best = g.fills.front().shading;
            bestDistance = distance;
        }
    }
    return best;
}

} // namespace finbook::model
