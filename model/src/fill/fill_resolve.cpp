// Fills → faces (the rules are in fill_resolve.h).
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <algorithm>
#include <iterator>
#include <optional>

namespace finbook::model {

namespace {
std::size_t shared(const std::vector<Id> &a, const std::vector<Id> &b)
{
    std::size_t n = 0;
    for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
        if (*i < *j)
            ++i;
        else if (*j < *i)
            ++j;
        else
            ++n, ++i, ++j;
    }
    return n;
}

bool contains(const std::vector<Id> &sorted, Id id)
{
    return std::binary_search(sorted.begin(), sorted.end(), id);
}

int primaryFace(const ObjectRegions &regions, const Fill &fill)
{
    const int atSeed = regions.faceAt(fill.seed);
    if (atSeed >= 0 &&
        (fill.strokes.empty() || shared(regions.faceStrokeIds(atSeed), fill.strokes) > 0))
        return atSeed;
    int best = -1;
    std::size_t bestShared = 0;
    double bestDistance = 0;
    for (int f = 0; f < regions.faceCount(); ++f) {
        const std::size_t n = shared(regions.faceStrokeIds(f), fill.strokes);
        const auto &seed = regions.regions().faces[std::size_t(f)].seed;
        const double d = QLineF(fill.seed, QPointF(seed.x(), seed.y())).length();
        if (n > bestShared || (n == bestShared && n > 0 && d < bestDistance)) {
            best = f;
            bestShared = n;
            bestDistance = d;
        }
    }
    return best >= 0 && 2 * bestShared >= fill.strokes.size() ? best : -1;
}

// The faces a split of `primary` made: see the header.
std::vector<int> splitFaces(const ObjectRegions &regions, const Fill &fill, int primary)
{
    std::vector<Id> cutting; // strokes bounding the fill's faces that it did not know
    const auto addCutting = [&](int face) {
        for (Id id : regions.faceStrokeIds(face))
            if (!contains(fill.strokes, id) && !contains(cutting, id))
                cutting.insert(std::upper_bound(cutting.begin(), cutting.end(), id), id);
    };
    addCutting(primary);
    std::vector<int> faces{primary};
    for (bool grew = !cutting.empty(); grew;) {
        grew = false;
        for (int f = 0; f < regions.faceCount(); ++f) {
            if (std::find(faces.begin(), faces.end(), f) != faces.end())
                continue;
            const auto &ids = regions.faceStrokeIds(f);
            bool touchesCut = false, touchesFill = false, foreign = false;
            for (Id id : ids) {
                if (contains(fill.strokes, id))
                    touchesFill = true;
                else if (contains(cutting, id))
                    touchesCut = true;
                else
                    foreign = true;
            }
            if (touchesCut && touchesFill && !foreign) {
                faces.push_back(f);
                grew = true;
            }
        }
    }
    return faces;
}
} // namespace

std::vector<int> faceFills(const ObjectRegions &regions, const std::vector<Fill> &fills)
{
    std::vector<int> out(std::size_t(regions.faceCount()), -1);
    for (std::size_t i = 0; i < fills.size(); ++i) {
        const int primary = primaryFace(regions, fills[i]);
        if (primary < 0)
            continue;
        for (int f : splitFaces(regions, fills[i], primary))
            out[std::size_t(f)] = int(i);
    }
    return out;
}

Fill fillOfFace(const ObjectRegions &regions, int face, QRgb color)
{
    const auto &seed = regions.regions().faces[std::size_t(face)].seed;
    return Fill{color, QPointF(seed.x(), seed.y()), regions.faceStrokeIds(face), {}};
}

std::optional<std::vector<Fill>> fillsWithFace(const ObjectRegions &regions,
                                               const std::vector<Fill> &fills, int face, QRgb color)
{
    if (face < 0 || face >= regions.faceCount())
        return std::nullopt;
    const int shown = faceFills(regions, fills)[std::size_t(face)];
    std::vector<Fill> out = fills;
    if (shown < 0) {
        out.push_back(fillOfFace(regions, face, color));
        // A new fill is shaded as the object's others are (the Shading panel sets them all).
        if (!fills.empty())
            out.back().shading = fills.back().shading;
        return out;
    }
    if (fills[std::size_t(shown)].color == color)
        return std::nullopt;
    // Recolouring keeps the fill where it is (its other split halves too): only the colour.
    out[std::size_t(shown)].color = color;
    return out;
}

std::optional<std::vector<Fill>> fillsWithoutFace(const ObjectRegions &regions,
                                                  const std::vector<Fill> &fills, int face)
{
    if (face < 0 || face >= regions.faceCount())
        return std::nullopt;
    const std::vector<int> shown = faceFills(regions, fills);
    if (shown[std::size_t(face)] < 0)
        return std::nullopt;
    // Every fill that would show here once the one on top is gone goes too.
    std::vector<Fill> out = fills;
    for (;;) {
        const int top = faceFills(regions, out)[std::size_t(face)];
        if (top < 0)
            break;
        out.erase(out.begin() + top);
    }
    return out;
}

std::optional<std::vector<Fill>> fillsWithAllFaces(const ObjectRegions &regions,
                                                   const std::vector<Fill> &fills, QRgb color)
{
    const std::vector<int> shown = faceFills(regions, fills);
    std::vector<Fill> out = fills;
    for (int f = 0; f < regions.faceCount(); ++f)
        if (shown[std::size_t(f)] < 0) {
            out.push_back(fillOfFace(regions, f, color));
            if (!fills.empty())
                out.back().shading = fills.back().shading;
        }
    if (out.size() == fills.size())
        return std::nullopt;
    return out;
}

std::vector<Fill> fillsAfterBake(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap)
{
    std::vector<Fill> out = group.fills;
    if (out.empty())
        return out;
    const ObjectRegionsPtr before = objectRegions(group, closeGap);
    const std::vector<int> shown = faceFills(*before, group.fills);
    StrokeGroup after;
    after.strokes = baked;
    const ObjectRegionsPtr regions = objectRegions(after, closeGap);
    for (std::size_t i = 0; i < out.size(); ++i) {
        QPainterPath where; // the fill as it shows now
        for (int f = 0; f < before->faceCount(); ++f)
            if (shown[std::size_t(f)] == int(i))
                where.addPath(before->displayedPath(group, f));
        where.setFillRule(Qt::WindingFill);
        int best = -1;
        double bestArea = 0;
        for (int f = 0; f < regions->faceCount(); ++f) {
            const geometry::Face &face = regions->regions().faces[std::size_t(f)];
            if (face.area > bestArea && where.contains(QPointF(face.seed.x(), face.seed.y()))) {
                best = f;
                bestArea = face.area;
            }
        }
        if (best >= 0)
            out[i].seed = fillOfFace(*regions, best, out[i].color).seed;
    }
    // A face the baked lines cut off from the one its fill moved to (where a limb passed over
    // the body, a fold) shows what the pose showed there: the topmost fill as drawn, a
    // cut-out pose's layers and round joints included.
    DocumentSettings settings;
    settings.closeGap = closeGap;
    const std::vector<PaintLayer> layers = paintLayers(group, settings);
    const std::vector<int> filled = faceFills(*regions, out);
    for (int f = 0; f < regions->faceCount(); ++f) {
        if (filled[std::size_t(f)] >= 0)
            continue;
        const geometry::Face &face = regions->regions().faces[std::size_t(f)];
        const QPointF seed(face.seed.x(), face.seed.y());
        std::optional<QRgb> colour;
        for (auto layer = layers.rbegin(); layer != layers.rend() && !colour; ++layer)
            for (auto item = layer->fills.rbegin(); item != layer->fills.rend(); ++item)
                if (item->path.contains(seed)) {
                    colour = item->color;
                    break;
                }
        if (!colour)
            continue;
        Fill added = fillOfFace(*regions, f, *colour);
        const auto same = std::find_if(group.fills.rbegin(), group.fills.rend(),
                                       [&](const Fill &fill) { return fill.color == *colour; });
        if (same != group.fills.rend())
            added.shading = same->shading;
        out.push_back(std::move(added));
    }
    return out;
}

int displayedFaceAt(const ObjectRegions &regions, const StrokeGroup &group, QPointF p)
{
    if (!group.isDeformed())
        return regions.faceAt(p);
    // Innermost: the smallest face whose displayed outline holds p.
    int best = -1;
    double bestArea = 0;
    for (int f = 0; f < regions.faceCount(); ++f) {
        if (!regions.displayedPath(group, f).contains(p))
            continue;
        const double area = regions.regions().faces[std::size_t(f)].area;
        if (best < 0 || area < bestArea) {
            best = f;
            bestArea = area;
        }
    }
    return best;
}

} // namespace finbook::model
