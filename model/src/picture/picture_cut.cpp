// cutOutPictureLayers: the cut texture mesh posed piece by piece, with sockets under it.
#include "picture_cut.h"

#include <cmath>
#include <numbers>

namespace finbook::model {

namespace {

// The disk of `cut` at rest as a fan (centre, then kSocketSegments points round it, starting on
// the cut), moved with the limb's bone (the cut's child joint). It is textured from the limb's
// own half of the disk, mirrored across the cut on the other half: turned with the limb, the
// half that lay on the parent's side would carry the parent's pixels (a body's colour) out past
// the parent's outline, where the limb's round end belongs.
void addSocket(PictureLayers &layers, const deform::JointCut &cut, const QTransform &toTexture,
               const deform::Skeleton &rest, const deform::PosedSkeleton &posed)
{
    const Eigen::Index j = cut.joint, child = cut.child;
    if (!(cut.round > 0.0) || j < 0 || child < 0 || j >= rest.joints.rows() ||
        child >= rest.joints.rows() || child >= posed.joints.rows() ||
        child >= posed.worldAngles.size())
        return;
    // T_child(x) = R(Θ)(x − r_child) + p_child: the bone's own motion (skeleton.h).
    const double angle = posed.worldAngles(child);
    const double c = std::cos(angle), s = std::sin(angle);
    const Eigen::Vector2d restChild = rest.joints.row(child).transpose();
    const Eigen::Vector2d posedChild = posed.joints.row(child).transpose();
    const auto moved = [&](const Eigen::Vector2d &x) {
        const Eigen::Vector2d d = x - restChild;
        return QPointF(c * d.x() - s * d.y() + posedChild.x(),
                       s * d.x() + c * d.y() + posedChild.y());
    };
    const Eigen::Vector2d centre = rest.joints.row(j).transpose();
    // Along the cut, and across it towards the limb (a cut of no length: towards the child).
    Eigen::Vector2d along = cut.b - cut.a;
    if (!(along.norm() > 1e-9))
        along = Eigen::Vector2d(-(restChild - centre).y(), (restChild - centre).x());
    if (!(along.norm() > 1e-9))
        along = Eigen::Vector2d(1.0, 0.0);
    along.normalize();
    Eigen::Vector2d limb(-along.y(), along.x());
    if (limb.dot(restChild - centre) < 0.0)
        limb = -limb;
    static_assert(kSocketSegments % 2 == 0, "the cut's two ends are rim points");
    const int first = int(layers.vertices.size());
    for (int k = -1; k < kSocketSegments; ++k) {
        Eigen::Vector2d p = centre, texel = centre;
        if (k >= 0) {
            const double t = 2.0 * std::numbers::pi * k / kSocketSegments;
            p += cut.round * (std::cos(t) * along + std::sin(t) * limb);
            texel += cut.round * (std::cos(t) * along + std::abs(std::sin(t)) * limb);
        }
        layers.uv.push_back(toTexture.map(QPointF(texel.x(), texel.y())));
        layers.vertices.push_back(moved(p));
    }
    for (int k = 0; k < kSocketSegments; ++k)
        layers.faces.push_back({first, first + 1 + k, first + 1 + (k + 1) % kSocketSegments});
}

} // namespace

PictureLayers cutOutPictureLayers(const ObjectPicture &picture, const deform::CutMesh &cut,
                                  const Eigen::MatrixX2d &U, const deform::Skeleton &rest,
                                  const deform::PosedSkeleton &posed)
{
    PictureLayers layers;
    if (!picture.mesh || !picture.place.isInvertible() || cut.cuts.empty() ||
        U.rows() != cut.V.rows() || cut.source.size() != cut.V.rows() ||
        cut.piece.size() != cut.F.rows())
        return layers;
    const Eigen::MatrixX2d &uv = picture.mesh->uv;
    const QTransform toTexture = picture.place.inverted();
    layers.uv.reserve(std::size_t(U.rows()) + cut.cuts.size() * (kSocketSegments + 1));
    layers.vertices.reserve(layers.uv.capacity());
    layers.faces.reserve(std::size_t(cut.F.rows()) + cut.cuts.size() * kSocketSegments);
    for (const deform::JointCut &at : cut.cuts)
        addSocket(layers, at, toTexture, rest, posed);
    const int offset = int(layers.vertices.size());
    for (Eigen::Index v = 0; v < U.rows(); ++v) {
        const int from = cut.source(v);
        if (from < 0 || from >= uv.rows())
            return {};
        layers.uv.emplace_back(uv(from, 0), uv(from, 1));
        layers.vertices.emplace_back(U(v, 0), U(v, 1));
    }
    // The roots' piece (−1), then each cut's: a piece is drawn over the ones above it.
    for (int piece = -1; piece < int(cut.cuts.size()); ++piece)
        for (Eigen::Index t = 0; t < cut.F.rows(); ++t)
            if (cut.piece(t) == piece)
                layers.faces.push_back(
                    {offset + cut.F(t, 0), offset + cut.F(t, 1), offset + cut.F(t, 2)});
    return layers;
}

} // namespace finbook::model
