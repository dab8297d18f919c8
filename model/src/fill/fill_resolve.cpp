// Fills → faces (the rules are in fill_resolve.h).
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <algorithm>
#include <iterator>
#include <limits>
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

// How deep `p` lies in `polygon`: its distance to the nearest ring (outer or hole).
double depthIn(const geometry::Polygon &polygon, QPointF p)
{
    const Eigen::Vector2d q(p.x(), p.y());
    double best = std::numeric_limits<double>::infinity();
    const auto ring = [&](const Eigen::MatrixX2d &r) {
        for (Eigen::Index i = 0; i < r.rows(); ++i) {
            const Eigen::Vector2d a = r.row(i).transpose();
            const Eigen::Vector2d b = r.row((i + 1) % r.rows()).transpose();
            const Eigen::Vector2d d = b - a;
            const double len2 = d.squaredNorm();
            const double t = len2 > 0.0 ? std::clamp((q - a).dot(d) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, (a + t * d - q).norm());
        }
    };
    ring(polygon.outer);
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        ring(hole);
    return best;
}

// One region of a fill: its seed and its strokes (the fill's own, or one of Fill::more).
struct Place {
    const QPointF &seed;
    const std::vector<Id> &strokes;
};

Place placeOf(const Fill &fill, int k)
{
    if (k < 0)
        return {fill.seed, fill.strokes};
    const FillPlace &p = fill.more[std::size_t(k)];
    return {p.seed, p.strokes};
}

int primaryFace(const ObjectRegions &regions, const Place &fill)
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
std::vector<int> splitFaces(const ObjectRegions &regions, const Place &fill, int primary)
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

// Which fill, and which of its regions (−1 its first, k its Fill::more[k]), each face shows.
struct Owner {
    int fill = -1;
    int place = -1;
};

std::vector<Owner> faceOwners(const ObjectRegions &regions, const std::vector<Fill> &fills)
{
    // Each face goes to the fill region that claims it as its own and is tied best to the
    // strokes around it: first the one none of whose strokes now bounds another face instead
    // (fewest such strokes: a region whose outline moved away is not the face its seed is
    // left in, while new strokes meeting a face, a moved head touching an arm, do not make
    // it another face), then the larger share of strokes in common, a later one winning a
    // tie. So a fill whose region has gone, and whose seed now lies in a neighbour's region,
    // never takes that region from the neighbour's own fill (and never spreads from there).
    const auto n = std::size_t(regions.faceCount());
    std::vector<Owner> out(n);
    std::vector<double> claim(n, -std::numeric_limits<double>::infinity());
    std::vector<Id> bounding; // every stroke that bounds some face
    for (int f = 0; f < regions.faceCount(); ++f)
        bounding.insert(bounding.end(), regions.faceStrokeIds(f).begin(),
                        regions.faceStrokeIds(f).end());
    std::sort(bounding.begin(), bounding.end());
    bounding.erase(std::unique(bounding.begin(), bounding.end()), bounding.end());
    struct Claim {
        Owner owner;
        int face;
    };
    std::vector<Claim> claims;
    for (std::size_t i = 0; i < fills.size(); ++i)
        for (int k = -1; k < int(fills[i].more.size()); ++k) {
            const Place place = placeOf(fills[i], k);
            const int f = primaryFace(regions, place);
            if (f < 0)
                continue;
            claims.push_back({{int(i), k}, f});
            const auto &ids = regions.faceStrokeIds(f);
            const std::size_t common = shared(ids, place.strokes);
            const std::size_t either = ids.size() + place.strokes.size() - common;
            std::size_t elsewhere = 0; // the place's strokes that bound other faces only
            for (Id id : place.strokes)
                elsewhere += contains(bounding, id) && !contains(ids, id);
            // Lexicographic: the share (0-1) decides only between equal counts.
            const double tie =
                (either > 0 ? double(common) / double(either) : 1.0) - 2.0 * double(elsewhere);
            // On a tie, a fill's further region (made from a smaller face than its first,
            // fillsAfterBake) never takes a face from another fill's first region, and a first
            // region always takes it from a further one. Otherwise the seed lying deeper in
            // the face wins: two regions made one by erasing the line between them (each fill
            // tied as well to the strokes left) show the colour of the larger, whose seed
            // (the point furthest inside it) lies deep in the merged face, not the smaller's
            // near its edge, whichever was filled last. A later one wins an exact tie.
            const Owner &held = out[std::size_t(f)];
            bool takes = tie > claim[std::size_t(f)];
            if (tie == claim[std::size_t(f)]) {
                if (held.fill < 0 || (k < 0) != (held.place < 0)) {
                    takes = held.fill < 0 || k < 0;
                } else {
                    const auto &polygon = regions.regions().faces[std::size_t(f)].polygon;
                    const double mine = depthIn(polygon, place.seed);
                    const double theirs =
                        depthIn(polygon, placeOf(fills[std::size_t(held.fill)], held.place).seed);
                    takes = mine >= theirs;
                }
            }
            if (takes) {
                claim[std::size_t(f)] = tie;
                out[std::size_t(f)] = {int(i), k};
            }
        }
    // The halves of a region cut in two by new strokes keep its fill, unless another fill
    // claims them as its own.
    std::vector<Owner> spread = out;
    for (const Claim &c : claims) {
        const Owner &o = out[std::size_t(c.face)];
        if (o.fill != c.owner.fill || o.place != c.owner.place)
            continue;
        for (int half : splitFaces(regions, placeOf(fills[std::size_t(o.fill)], o.place), c.face))
            if (out[std::size_t(half)].fill < 0)
                spread[std::size_t(half)] = c.owner;
    }
    return spread;
}
} // namespace

std::vector<int> faceFills(const ObjectRegions &regions, const std::vector<Fill> &fills)
{
    const std::vector<Owner> owners = faceOwners(regions, fills);
    std::vector<int> out(owners.size());
    for (std::size_t f = 0; f < owners.size(); ++f)
        out[f] = owners[f].fill;
    return out;
}

Fill fillOfFace(const ObjectRegions &regions, int face, QRgb color)
{
    const auto &seed = regions.regions().faces[std::size_t(face)].seed;
    return Fill{color, QPointF(seed.x(), seed.y()), regions.faceStrokeIds(face), {}, {}};
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
    if (faceOwners(regions, fills)[std::size_t(face)].fill < 0)
        return std::nullopt;
    // Every fill region that would show here once the one on top is gone goes too. A fill of
    // several regions (Fill::more) loses only this one: the others stay coloured.
    std::vector<Fill> out = fills;
    for (;;) {
        const Owner top = faceOwners(regions, out)[std::size_t(face)];
        if (top.fill < 0)
            break;
        Fill &fill = out[std::size_t(top.fill)];
        if (fill.more.empty()) {
            out.erase(out.begin() + top.fill);
        } else if (top.place >= 0) {
            fill.more.erase(fill.more.begin() + top.place);
        } else { // its first region goes: the next one takes its place
            fill.seed = fill.more.front().seed;
            fill.strokes = std::move(fill.more.front().strokes);
            fill.more.erase(fill.more.begin());
        }
    }
    return out;
}

std::optional<std::vector<Fill>> fillsWithAllFaces(const ObjectRegions &regions,
                                                   const std::vector<Fill> &fills, QRgb color)
{
    const std::vector<int> shown = faceFills(regions, fills);
    std::vector<Fill> out = fills;
    // A face whose outline runs mostly along gap closures is one nobody drew (a wedge between
    // an outline and a line beside it): a click of the Fill tool still fills it, Fill All not.
    constexpr double kMostlyClosures = 0.5;
    for (int f = 0; f < regions.faceCount(); ++f)
        if (shown[std::size_t(f)] < 0 &&
            geometry::closureShare(regions.regions(), f) <= kMostlyClosures) {
            out.push_back(fillOfFace(regions, f, color));
            if (!fills.empty())
                out.back().shading = fills.back().shading;
        }
    if (out.size() == fills.size())
        return std::nullopt;
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
