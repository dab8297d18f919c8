// Skinning precompute and solve for a skeleton rig (deform/skeleton/*), in the shape the
// generic deform setup dispatches to.
#include "../deformation_text.h"

#include <finbook/geometry/embedding.h>
#include <finbook/model/skeleton/skeleton_setup.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
QString message(const deform::DeformError &e)
{
    return QString::fromStdString(e.message);
}
} // namespace

Expected<deform::Skeleton, QString> deformSkeleton(const SkeletonRig &rig)
{
    if (!rig.isValid() || rig.empty())
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    const Eigen::Index n = Eigen::Index(rig.joints.size());
    Eigen::MatrixX2d joints(n, 2);
    Eigen::VectorXi parent(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        joints.row(j) << rig.joints[std::size_t(j)].x(), rig.joints[std::size_t(j)].y();
        parent(j) = rig.parent[std::size_t(j)];
    }
    auto skeleton = deform::makeSkeleton(joints, parent);
    if (!skeleton)
        return unexpected(
            Deformation::tr("The skeleton cannot be used: %1").arg(message(skeleton.error())));
    return std::move(*skeleton);
}

Expected<deform::Skeleton, QString> skinningSkeleton(const SkeletonRig &rig)
{
    auto own = deformSkeleton(rig);
    if (!own || !rig.hangs() || rig.anchor.from == rig.anchor.to)
        return own;
    // The parent's bone joins as a tree of its own (two joints after the part's), so the
    // part's vertices along it take its motion and blend into the part's own bones.
    const Eigen::Index n = own->jointCount();
    Eigen::MatrixX2d joints(n + 2, 2);
    Eigen::VectorXi parent(n + 2);
    joints.topRows(n) = own->joints;
    parent.head(n) = own->parent;
    joints.row(n) << rig.anchor.from.x(), rig.anchor.from.y();
    joints.row(n + 1) << rig.anchor.to.x(), rig.anchor.to.y();
    parent(n) = -1;
    parent(n + 1) = int(n);
    auto skeleton = deform::makeSkeleton(joints, parent);
    if (!skeleton)
        return unexpected(
            Deformation::tr("The skeleton cannot be used: %1").arg(message(skeleton.error())));
    return std::move(*skeleton);
}

Expected<deform::PosedSkeleton, QString> posedSkinningSkeleton(const deform::Skeleton &skeleton,
                                                               const SkeletonRig &rig)
{
    deform::SkeletonPose pose = skeletonPose(rig);
    const Eigen::Index own = pose.angles.size();
    if (skeleton.jointCount() < own)
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    pose.angles.conservativeResize(skeleton.jointCount());
    pose.angles.tail(skeleton.jointCount() - own).setZero();
    auto posed = deform::forwardKinematics(skeleton, pose);
    if (!posed)
        return unexpected(
            Deformation::tr("The bones could not be posed: %1").arg(message(posed.error())));
    if (!rig.hangs())
        return std::move(*posed);
    // The part's own pose happens in its parent bone's rest frame; that bone's motion
    // follows. The parent's bone itself (if it skins) moves by that motion alone.
    const RigidMotion &m = rig.anchor.motion;
    const double c = std::cos(m.angle), s = std::sin(m.angle);
    deform::BoneTransform A;
    A << c, -s, m.shift.x(), s, c, m.shift.y();
    for (Eigen::Index j = 0; j < skeleton.jointCount(); ++j) {
        deform::BoneTransform &T = posed->transforms[std::size_t(j)];
        if (j < own) {
            T.col(2) = A.leftCols<2>() * T.col(2) + A.col(2);
            T.leftCols<2>() = A.leftCols<2>() * T.leftCols<2>();
            posed->joints.row(j) =
                (A.leftCols<2>() * posed->joints.row(j).transpose() + A.col(2)).transpose();
            posed->worldAngles(j) += m.angle;
        } else {
            T = A;
            posed->joints.row(j) =
                (A.leftCols<2>() * skeleton.joints.row(j).transpose() + A.col(2)).transpose();
            posed->worldAngles(j) = m.angle;
        }
    }
    return std::move(*posed);
}

deform::SkeletonPose skeletonPose(const SkeletonRig &rig)
{
    deform::SkeletonPose pose;
    pose.angles = Eigen::VectorXd::Zero(Eigen::Index(rig.joints.size()));
    for (std::size_t j = 0; j < rig.angles.size() && j < rig.joints.size(); ++j)
        pose.angles(Eigen::Index(j)) = rig.angles[j];
    pose.rootOffset = {rig.rootOffset.x(), rig.rootOffset.y()};
    return pose;
}

Expected<std::shared_ptr<const SkeletonSetup>, QString>
buildSkeletonSetup(const MeshedObject &meshed, const SkeletonRig &rig,
                   const deform::ArapOptions &options, const std::function<bool()> &cancelled)
{
    auto skeleton = skinningSkeleton(rig);
    if (!skeleton)
        return unexpected(skeleton.error());
    auto setup = std::make_shared<SkeletonSetup>();
    setup->skeleton = std::move(*skeleton);
    const Eigen::MatrixX2d &V = meshed.mesh.V;
    const Eigen::MatrixX3i &F = meshed.mesh.F;
    auto weights = deform::computeSkinningWeights(V, F, setup->skeleton, {}, cancelled);
    if (!weights)
        return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                              .arg(message(weights.error())));
    setup->weights = *weights;
    setup->vertices = deform::bindVertices(*setup->weights, V);
    // The rigid mode leaves each joint's flesh to the ARAP solve (joint zones of one inscribed
    // radius): chosen over plain bone pins with `finbook-bench limbs` (README).
    Eigen::VectorXd radius = Eigen::VectorXd::Zero(setup->skeleton.jointCount());
    for (std::size_t j = 0; j < rig.radius.size() && Eigen::Index(j) < radius.size(); ++j)
        radius(Eigen::Index(j)) = std::isfinite(rig.radius[j]) ? std::max(0.0, rig.radius[j]) : 0.0;
    if (rig.mode == SkinningMode::CutOut) {
        // Cut at the joints where limbs narrow, each piece skinned by its own bones, with the
        // Rigid mode's joint zones where it was not cut (chosen with `finbook-bench limbs`,
        // scheme cutout_layers).
        auto cut = deform::cutAtJoints(V, F, setup->skeleton, radius);
        if (!cut)
            return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                                  .arg(message(cut.error())));
        // The round ends reach the strokes' centre lines, where the fills end, not the mesh's
        // outline (a little way outside the ink): at rest a socket lies under the fill.
        const Eigen::MatrixX2d points = geometry::applyEmbedding(meshed.embedding, V, F);
        for (deform::JointCut &at : cut->cuts) {
            if (at.joint < 0 || at.joint >= setup->skeleton.jointCount())
                continue;
            const Eigen::Vector2d c = setup->skeleton.joints.row(at.joint).transpose();
            for (std::size_t s = 0; s + 1 < meshed.strokeOffsets.size(); ++s) {
                const auto first = Eigen::Index(meshed.strokeOffsets[s]);
                const auto end = std::min(Eigen::Index(meshed.strokeOffsets[s + 1]), points.rows());
                for (Eigen::Index i = first; i < end; ++i) {
                    const Eigen::Vector2d p = points.row(i).transpose();
                    const Eigen::Vector2d d =
                        i + 1 < end ? Eigen::Vector2d(points.row(i + 1).transpose() - p)
                                    : Eigen::Vector2d::Zero();
                    const double length2 = d.squaredNorm();
                    const double t =
                        length2 > 0.0 ? std::clamp((c - p).dot(d) / length2, 0.0, 1.0) : 0.0;
                    at.round = std::min(at.round, (p + t * d - c).norm());
                }
            }
        }
        const deform::SkinningWeights pieces =
            deform::cutOutWeights(*setup->weights, setup->skeleton, *cut);
        auto rigid = deform::rigidSkinPrecompute(
            cut->V, cut->F, deform::withJointZones(pieces, cut->V, setup->skeleton, radius),
            options, cancelled);
        if (!rigid)
            return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                                  .arg(message(rigid.error())));
        setup->cut = std::move(*cut);
        setup->cutRigid = *rigid;
        return std::shared_ptr<const SkeletonSetup>(std::move(setup));
    }
    const deform::SkinningWeights pins =
        deform::withJointZones(*setup->weights, V, setup->skeleton, radius);
    auto rigid = deform::rigidSkinPrecompute(V, F, pins, options, cancelled);
    if (!rigid)
        return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                              .arg(message(rigid.error())));
    setup->rigid = *rigid;
    return std::shared_ptr<const SkeletonSetup>(std::move(setup));
}

void addCutOutPieces(const SkeletonSetup &setup, const MeshedObject &meshed,
                     const Eigen::MatrixX2d &U, const SkeletonRig &rig, DeformedStrokes &out)
{
    if (!setup.cut || setup.cut->cuts.empty() || U.rows() != setup.cut->V.rows())
        return;
    const deform::CutMesh &cut = *setup.cut;
    const Eigen::VectorXi &triangle = meshed.embedding.I;
    out.pieceOf.resize(out.strokes.size());
    Eigen::Index row = 0;
    for (std::size_t s = 0; s < out.strokes.size(); ++s) {
        out.pieceOf[s].assign(out.strokes[s].size(), -1);
        for (std::int16_t &piece : out.pieceOf[s]) {
            const int t = row < triangle.size() ? triangle(row) : -1;
            if (t >= 0 && t < cut.piece.size())
                piece = std::int16_t(std::clamp(cut.piece(t), -1, 32767));
            ++row;
        }
    }
    // Outline loops of V rows as a posed path (non-zero rule).
    const auto posedPath = [&U](const std::vector<std::vector<int>> &loops) {
        QPainterPath path;
        path.setFillRule(Qt::WindingFill);
        for (const std::vector<int> &loop : loops) {
            if (loop.empty())
                continue;
            path.moveTo(U(loop[0], 0), U(loop[0], 1));
            for (std::size_t i = 1; i < loop.size(); ++i)
                path.lineTo(U(loop[i], 0), U(loop[i], 1));
            path.closeSubpath();
        }
        return path;
    };
    out.pieces.assign(cut.cuts.size(), QPainterPath());
    for (std::size_t piece = 0; piece < cut.outlines.size() && piece < out.pieces.size(); ++piece)
        out.pieces[piece] = posedPath(cut.outlines[piece]);
    out.body = posedPath(cut.rootOutline);
    // Each piece's motion where it is rigid (2D Procrustes of its vertices, rest → posed).
    const int layers = int(cut.cuts.size()) + 1;
    std::vector<std::vector<int>> members;
    members.resize(std::size_t(layers));
    {
        std::vector<char> seen(std::size_t(cut.V.rows()), 0);
        for (Eigen::Index t = 0; t < cut.F.rows(); ++t)
            for (int k = 0; k < 3; ++k) {
                const int v = cut.F(t, k);
                if (!seen[std::size_t(v)]) {
                    seen[std::size_t(v)] = 1;
                    members[std::size_t(std::clamp(cut.piece(t) + 1, 0, layers - 1))].push_back(v);
                }
            }
    }
    out.motions.assign(std::size_t(layers), std::nullopt);
    for (int layer = 0; layer < layers; ++layer) {
        const std::vector<int> &vs = members[std::size_t(layer)];
        if (vs.empty())
            continue;
        Eigen::Vector2d restMean = Eigen::Vector2d::Zero(), posedMean = Eigen::Vector2d::Zero();
        for (int v : vs) {
            restMean += cut.V.row(v).transpose();
            posedMean += U.row(v).transpose();
        }
        restMean /= double(vs.size());
        posedMean /= double(vs.size());
        double dot = 0.0, cross = 0.0;
        for (int v : vs) {
            const Eigen::Vector2d r = cut.V.row(v).transpose() - restMean;
            const Eigen::Vector2d p = U.row(v).transpose() - posedMean;
            dot += r.dot(p);
            cross += r.x() * p.y() - r.y() * p.x();
        }
        const double angle = std::atan2(cross, dot);
        const double c = std::cos(angle), s = std::sin(angle);
        const Eigen::Vector2d t = posedMean - Eigen::Vector2d(c * restMean.x() - s * restMean.y(),
                                                              s * restMean.x() + c * restMean.y());
        double worst = 0.0;
        for (int v : vs) {
            const Eigen::Vector2d r = cut.V.row(v).transpose();
            const Eigen::Vector2d moved(c * r.x() - s * r.y() + t.x(),
                                        s * r.x() + c * r.y() + t.y());
            worst = std::max(worst, (moved - U.row(v).transpose()).norm());
        }
        // Rigid to within a hundredth of a pixel (a piece with a bent joint inside is not).
        if (std::isfinite(worst) && worst <= 0.01)
            out.motions[std::size_t(layer)] = QTransform(c, s, -s, c, t.x(), t.y());
    }
    // Each cut's round end, at its joint as posed (the same from either piece).
    out.sockets.assign(cut.cuts.size(), QPainterPath());
    out.socketAbove.assign(cut.cuts.size(), -1);
    const auto posed = posedSkinningSkeleton(setup.skeleton, rig);
    for (std::size_t piece = 0; piece < cut.cuts.size(); ++piece) {
        out.socketAbove[piece] = piece < cut.parentPiece.size() ? cut.parentPiece[piece] : -1;
        const deform::JointCut &at = cut.cuts[piece];
        if (!posed || at.round <= 0.0 || at.joint < 0 || at.joint >= posed->joints.rows())
            continue;
        const Eigen::Vector2d c = posed->joints.row(at.joint).transpose();
        out.sockets[piece].addEllipse(QPointF(c.x(), c.y()), at.round, at.round);
    }
}

Expected<Eigen::MatrixX2d, QString>
solveSkeleton(const MeshedObject &meshed, const SkeletonSetup &setup, const SkeletonRig &rig)
{
    auto posed = posedSkinningSkeleton(setup.skeleton, rig);
    if (!posed)
        return unexpected(posed.error());
    Eigen::MatrixX2d U;
    if (setup.cut && setup.cutRigid) {
        U = setup.cut->V;
        auto solved = deform::rigidSkinSolve(*setup.cutRigid, *posed, U);
        if (!solved)
            return unexpected(
                Deformation::tr("The bones could not be posed: %1").arg(message(solved.error())));
    } else if (rig.mode == SkinningMode::LinearBlend) {
        if (auto error = deform::skin(setup.vertices, *posed, U))
            return unexpected(
                Deformation::tr("The bones could not be posed: %1").arg(message(*error)));
    } else if (setup.rigid) {
        U = meshed.mesh.V;
        auto solved = deform::rigidSkinSolve(*setup.rigid, *posed, U);
        if (!solved)
            return unexpected(
                Deformation::tr("The bones could not be posed: %1").arg(message(solved.error())));
    } else {
        U = meshed.mesh.V;
    }
    return U;
}

} // namespace finbook::model
