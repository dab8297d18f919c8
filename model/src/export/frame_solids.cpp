#include <finbook/geometry/embedding.h>
#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/inflate/layers.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/export/frame_solids.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/render.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>

namespace finbook::model {

namespace {
bool hasPicture(const StrokeGroup &group)
{
    return group.picture && pictureIsValid(*group.picture);
}

bool hasPoints(const StrokeGroup &group)
{
    if (hasPicture(group))
        return true;
    return std::any_of(group.strokes.begin(), group.strokes.end(),
                       [](const Stroke &s) { return s.data && !s.data->points.empty(); });
}

// Whether every point lies within the widest pen of one straight line: a dot or a straight
// line. Its pen band would mesh, but only as a bead or a rod one pen wide, not a body the
// drawing shows (principal axes of the points; their spread across the main one).
bool isDotOrStraightLine(const std::vector<StrokeDataPtr> &strokes)
{
    std::vector<Eigen::Vector2d> points;
    double widest = 0.0;
    for (const StrokeDataPtr &data : strokes) {
        if (!data)
            continue;
        if (std::isfinite(data->width))
            widest = std::max(widest, double(data->width));
        for (const StrokePoint &p : data->points)
            if (std::isfinite(p.x) && std::isfinite(p.y))
                points.emplace_back(p.x, p.y);
    }
    if (points.empty())
        return true;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d &p : points)
        mean += p;
    mean /= double(points.size());
    Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d &p : points)
        covariance += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> axes(covariance);
    const Eigen::Vector2d across = axes.eigenvectors().col(0); // the smaller eigenvalue's
    double low = 0.0, high = 0.0;
    for (const Eigen::Vector2d &p : points) {
        const double t = across.dot(p - mean);
        low = std::min(low, t);
        high = std::max(high, t);
    }
    return high - low <= std::max(widest, 2.0);
}

bool usable(const geometry::InflatedSolid &solid)
{
    return solid.F.rows() > 0 && solid.V.allFinite() && solid.N.allFinite() &&
           geometry::signedVolume(solid) > 0.0;
}

// Why an object has no solid.
enum class NoSolid { DotOrLine, TooFar, Failed, OverBudget };

bool tooFar(const std::vector<StrokeDataPtr> &strokes)
{
    for (const StrokeDataPtr &data : strokes)
        if (data)
            for (const StrokePoint &p : data->points)
                if (std::abs(p.x) > kMaxModelCoordinate || std::abs(p.y) > kMaxModelCoordinate)
                    return true;
    return false;
}

// An object whose every stroke closes a region by itself, two or more of them (a body and
// an arm drawn over it): one closed solid per stroke's region (geometry/inflate/layers.h),
// in one object, so the arm stays an arm in the 3D model instead of melting into the body.
// nullopt for any other object (it exports as its silhouette) or when a layer fails;
// OverBudget as soon as its layers pass `budget` vertices.
Expected<std::optional<geometry::InflatedSolid>, NoSolid>
layeredSolid(const std::vector<geometry::StrokeInput> &inputs, const geometry::MeshOptions &options,
             qint64 budget)
{
    if (inputs.size() < 2)
        return std::optional<geometry::InflatedSolid>();
    const double gap =
        options.regions.closeGap >= 0.0 ? options.regions.closeGap : geometry::autoCloseGap(inputs);
    const std::vector<geometry::Layer> layers = geometry::strokeLayers(inputs, gap);
    if (layers.size() != inputs.size())
        return std::optional<geometry::InflatedSolid>();
    geometry::InflatedSolid all;
    for (const geometry::Layer &layer : layers) {
        const auto mesh = geometry::buildObjectMesh(layer.region, options);
        if (!mesh)
            return std::optional<geometry::InflatedSolid>();
        const auto inflation = geometry::inflateObjectMesh(*mesh);
        if (!inflation)
            return std::optional<geometry::InflatedSolid>();
        const geometry::InflatedSolid solid = geometry::inflatedSolid(*inflation);
        if (!usable(solid))
            return std::optional<geometry::InflatedSolid>();
        if (all.V.rows() + solid.V.rows() > budget)
            return unexpected(NoSolid::OverBudget);
        const Eigen::Index v = all.V.rows(), f = all.F.rows();
        all.V.conservativeResize(v + solid.V.rows(), 3);
        all.N.conservativeResize(v + solid.N.rows(), 3);
        all.F.conservativeResize(f + solid.F.rows(), 3);
        all.V.bottomRows(solid.V.rows()) = solid.V;
        all.N.bottomRows(solid.N.rows()) = solid.N;
        all.F.bottomRows(solid.F.rows()) = solid.F.array() + int(v);
    }
    return std::optional<geometry::InflatedSolid>(std::move(all));
}

// The object's shape as it shows now: its displayed strokes, meshed as the deformers mesh
// its rest drawing (same density), with the gaps closed as its fills see them. At most
// `budget` vertices.
Expected<geometry::InflatedSolid, NoSolid> solidOf(const StrokeGroup &group, double closeGap,
                                                   qint64 budget)
{
    MeshKey key;
    key.density = group.meshDensity;
    for (const Stroke &s : posedStrokes(group))
        key.strokes.push_back(s.data);
    if (tooFar(key.strokes))
        return unexpected(NoSolid::TooFar);
    if (isDotOrStraightLine(key.strokes))
        return unexpected(NoSolid::DotOrLine);
    geometry::MeshOptions options;
    options.density = std::clamp(group.meshDensity, kMinMeshDensity, kMaxMeshDensity);
    options.regions = regionsOptions(closeGap);
    const std::vector<geometry::StrokeInput> inputs = strokeInputs(key);
    auto layered = layeredSolid(inputs, options, budget);
    if (!layered)
        return unexpected(layered.error());
    if (*layered)
        return std::move(**layered);
    const auto mesh = geometry::buildObjectMesh(inputs, options);
    if (!mesh)
        return unexpected(NoSolid::Failed);
    if (2 * mesh->V.rows() > budget) // the solid has a front and a back
        return unexpected(NoSolid::OverBudget);
    const auto inflation = geometry::inflateObjectMesh(*mesh);
    if (!inflation)
        return unexpected(NoSolid::Failed);
    geometry::InflatedSolid solid = geometry::inflatedSolid(*inflation);
    if (!usable(solid))
        return unexpected(NoSolid::Failed);
    if (solid.V.rows() > budget)
        return unexpected(NoSolid::OverBudget);
    return solid;
}

// A picture object's solid: its texture mesh at rest inflated, textured (UV from each vertex's
// rest position through the picture's place), then every vertex carried where the pose shows
// the picture (through the rest mesh's triangles), its normals made anew from the posed faces.
Expected<geometry::InflatedSolid, NoSolid> pictureSolid(const StrokeGroup &group, qint64 budget)
{
    const ObjectPicture &picture = *group.picture;
    const Eigen::MatrixX2d rest = picture.restVertices();
    const Eigen::MatrixX3i &F = picture.mesh->F;
    for (Eigen::Index i = 0; i < rest.rows(); ++i)
        if (std::abs(rest(i, 0)) > kMaxModelCoordinate ||
            std::abs(rest(i, 1)) > kMaxModelCoordinate)
            return unexpected(NoSolid::TooFar);
    const auto mesh = geometry::objectMeshFrom(rest, F);
    if (!mesh)
        return unexpected(NoSolid::Failed);
    if (2 * mesh->V.rows() > budget)
        return unexpected(NoSolid::OverBudget);
    const auto inflation = geometry::inflateObjectMesh(*mesh);
    if (!inflation)
        return unexpected(NoSolid::Failed);
    geometry::InflatedSolid solid = geometry::inflatedSolid(*inflation);
    if (!usable(solid) || solid.V.rows() > budget)
        return unexpected(usable(solid) ? NoSolid::OverBudget : NoSolid::Failed);
    // Where each vertex lies on the rest canvas (y down), and so in the picture.
    Eigen::MatrixX2d at(solid.V.rows(), 2);
    at.col(0) = solid.V.col(0);
    at.col(1) = -solid.V.col(1);
    const QTransform toTexture = picture.place.inverted();
    const QSizeF size = picture.data->image.size();
    solid.UV.resize(solid.V.rows(), 2);
    for (Eigen::Index i = 0; i < at.rows(); ++i) {
        const QPointF t = toTexture.map(QPointF(at(i, 0), at(i, 1)));
        solid.UV.row(i) << t.x() / size.width(), t.y() / size.height();
    }
    const Eigen::MatrixX2d shown = shownPictureVertices(group);
    if (shown.rows() != rest.rows() || shown == rest)
        return solid;
    const Eigen::MatrixX2d posed = geometry::applyEmbedding(geometry::embed(rest, F, at), shown, F);
    if (!posed.allFinite())
        return unexpected(NoSolid::Failed);
    solid.V.col(0) = posed.col(0);
    solid.V.col(1) = -posed.col(1);
    solid.N.setZero();
    for (Eigen::Index f = 0; f < solid.F.rows(); ++f) {
        const Eigen::Vector3d a = solid.V.row(solid.F(f, 0)), b = solid.V.row(solid.F(f, 1)),
                              c = solid.V.row(solid.F(f, 2));
        const Eigen::Vector3d n = (b - a).cross(c - a); // area-weighted, outward
        for (int k = 0; k < 3; ++k)
            solid.N.row(solid.F(f, k)) += n.transpose();
    }
    for (Eigen::Index i = 0; i < solid.N.rows(); ++i) {
        const double length = solid.N.row(i).norm();
        if (length > 0.0)
            solid.N.row(i) /= length;
        else
            solid.N.row(i) << 0.0, 0.0, 1.0;
    }
    if (!usable(solid))
        return unexpected(NoSolid::Failed);
    return solid;
}
} // namespace

QRgb objectExportColor(const StrokeGroup &group, double closeGap)
{
    if (!group.fills.empty()) {
        const ObjectRegionsPtr regions = objectRegions(group, closeGap);
        const std::vector<int> shown = faceFills(*regions, group.fills);
        std::vector<double> area(group.fills.size(), 0.0);
        for (std::size_t face = 0; face < shown.size(); ++face)
            if (shown[face] >= 0)
                area[std::size_t(shown[face])] += regions->regions().faces[face].area;
        const auto largest = std::max_element(area.begin(), area.end());
        if (*largest > 0.0)
            return group.fills[std::size_t(largest - area.begin())].color;
    }
    for (const Stroke &s : group.strokes)
        if (s.data)
            return s.data->color;
    return 0xff000000;
}

std::optional<FrameSolids> frameSolids(const Frame &frame, const DocumentSettings &settings,
                                       const SolidsProgress &progress, qint64 maxVertices)
{
    FrameSolids out;
    for (const StrokeGroup &group : frame.groups)
        out.candidates += group.visible && hasPoints(group) ? 1 : 0;
    // Objects showing the very same rest strokes at the same density (pasted copies in place)
    // have the same solid: it is made once and copied. (A posed object's strokes are made
    // afresh, so it is never taken for another.)
    std::map<std::pair<std::vector<const StrokeData *>, double>, std::size_t> made;
    int done = 0;
    for (const StrokeGroup &group : frame.groups) {
        if (!group.visible || !hasPoints(group))
            continue;
        std::pair<std::vector<const StrokeData *>, double> key{{}, group.meshDensity};
        for (const Stroke &s : group.strokes)
            key.first.push_back(s.data.get());
        const bool shared = !group.isDeformed() && !hasPicture(group);
        Expected<geometry::InflatedSolid, NoSolid> solid = unexpected(NoSolid::Failed);
        if (const auto same = shared ? made.find(key) : made.end(); same != made.end()) {
            const geometry::InflatedSolid &copy = out.objects[same->second].solid;
            if (out.vertices + copy.V.rows() > maxVertices)
                solid = unexpected(NoSolid::OverBudget);
            else
                solid = copy;
        } else {
            solid = hasPicture(group)
                        ? pictureSolid(group, maxVertices - out.vertices)
                        : solidOf(group, settings.closeGap, maxVertices - out.vertices);
            if (solid && shared)
                made.emplace(std::move(key), out.objects.size());
        }
        if (solid) {
            out.vertices += solid->V.rows();
            out.objects.push_back(
                {group.id, group.name,
                 hasPicture(group) ? QRgb(0xffffffff) : objectExportColor(group, settings.closeGap),
                 std::move(*solid), hasPicture(group) ? group.picture->data : nullptr});
        } else if (solid.error() == NoSolid::OverBudget) {
            out.tooLarge = true;
            return out;
        } else {
            ++out.skipped;
            out.tooFar += solid.error() == NoSolid::TooFar ? 1 : 0;
        }
        if (progress && !progress(++done, out.candidates))
            return std::nullopt;
    }
    return out;
}

} // namespace finbook::model
