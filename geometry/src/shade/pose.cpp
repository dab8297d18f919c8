// Moving-least-squares rigid posing of rest points by stroke controls (shade/pose.h).
#include <finbook/geometry/shade/pose.h>

#include <queue>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace finbook::geometry {

PoseWeights poseWeights(const Eigen::MatrixX2d &points, const Eigen::MatrixX2d &controls, int k,
                        double epsilon)
{
    k = std::max(k, 1);
    if (!(epsilon > 0.0))
        epsilon = 1.0;
    std::vector<int> finite;
    for (Eigen::Index c = 0; c < controls.rows(); ++c)
        if (controls.row(c).allFinite())
            finite.push_back(int(c));
    const int kk = std::min<int>(k, int(finite.size()));
    PoseWeights w;
    w.rest = controls;
    w.index = Eigen::MatrixXi::Constant(std::max(kk, 1), points.rows(), -1);
    w.weight = Eigen::MatrixXd::Zero(std::max(kk, 1), points.rows());
    w.offset = Eigen::MatrixX2d::Zero(points.rows(), 2);
    using Near = std::pair<double, int>; // squared distance, control; max-heap keeps the k best
    std::vector<Near> heap;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::RowVector2d p = points.row(i);
        if (!p.allFinite())
            continue;
        if (kk == 0) {
            w.offset.row(i) = p; // applyPose keeps it in place
            continue;
        }
        heap.clear();
        for (int c : finite) {
            const double d2 = (controls.row(c) - p).squaredNorm();
            if (int(heap.size()) < kk) {
                heap.emplace_back(d2, c);
                std::push_heap(heap.begin(), heap.end());
            } else if (d2 < heap.front().first) {
                std::pop_heap(heap.begin(), heap.end());
                heap.back() = {d2, c};
                std::push_heap(heap.begin(), heap.end());
            }
        }
        double total = 0.0;
        Eigen::RowVector2d centroid = Eigen::RowVector2d::Zero();
        for (int j = 0; j < int(heap.size()); ++j) {
            const double weight = 1.0 / (heap[std::size_t(j)].first + epsilon * epsilon);
            w.index(j, i) = heap[std::size_t(j)].second;
            w.weight(j, i) = weight;
            total += weight;
        }
        if (!(total > 0.0) || !std::isfinite(total)) { // distances beyond double's range
            w.index.col(i).setConstant(-1);
            w.weight.col(i).setZero();
            w.offset.row(i) = p;
            continue;
        }
        for (int j = 0; j < int(heap.size()); ++j) {
            w.weight(j, i) /= total;
            centroid += w.weight(j, i) * controls.row(w.index(j, i));
        }
        w.offset.row(i) = p - centroid;
    }
    return w;
}

PosedPoints applyPose(const PoseWeights &weights, const Eigen::MatrixX2d &posed, bool withAngle)
{
    const Eigen::Index n = weights.offset.rows();
    const Eigen::Index k = weights.index.rows();
    // Each control as shown (its rest place where the pose has none), read once.
    Eigen::MatrixX2d shown = weights.rest;
    for (Eigen::Index c = 0; c < shown.rows() && c < posed.rows(); ++c)
        if (std::isfinite(posed(c, 0)) && std::isfinite(posed(c, 1)))
            shown.row(c) = posed.row(c);
    PosedPoints out;
    out.V.resize(n, 2);
    if (withAngle)
        out.angle = Eigen::VectorXd::Zero(n);
    out.turn.resize(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        // One pass: with weights summing to 1, Σw (p − p*)·(q − q*) = Σw p·q − p*·q*, and the
        // same for the cross product.
        double px = 0.0, py = 0.0, qx = 0.0, qy = 0.0, dot = 0.0, cross = 0.0;
        bool any = false;
        for (Eigen::Index j = 0; j < k; ++j) {
            const int c = weights.index(j, i);
            if (c < 0)
                continue;
            any = true;
            const double w = weights.weight(j, i);
            const double rx = weights.rest(c, 0), ry = weights.rest(c, 1);
            const double sx = shown(c, 0), sy = shown(c, 1);
            px += w * rx;
            py += w * ry;
            qx += w * sx;
            qy += w * sy;
            dot += w * (rx * sx + ry * sy);
            cross += w * (rx * sy - ry * sx);
        }
        const double ox = weights.offset(i, 0), oy = weights.offset(i, 1);
        if (!any) {
            out.V.row(i) << ox, oy; // no control: the offset is the point itself
            out.turn.row(i) << 1.0, 0.0;
            continue;
        }
        const double a = dot - (px * qx + py * qy);
        const double b = cross - (px * qy - py * qx);
        const double length = std::sqrt(a * a + b * b);
        const double cs = length > 0.0 ? a / length : 1.0, sn = length > 0.0 ? b / length : 0.0;
        if (withAngle)
            out.angle(i) = std::atan2(sn, cs);
        out.turn.row(i) << cs, sn;
        out.V(i, 0) = qx + cs * ox - sn * oy;
        out.V(i, 1) = qy + sn * ox + cs * oy;
    }
    return out;
}

Eigen::MatrixX3d rotateNormals(const Eigen::MatrixX3d &normals, const Eigen::VectorXd &angle)
{
    Eigen::MatrixX3d out = normals;
    for (Eigen::Index i = 0; i < normals.rows() && i < angle.size(); ++i) {
        const double cs = std::cos(angle(i)), sn = std::sin(angle(i));
        out(i, 0) = cs * normals(i, 0) - sn * normals(i, 1);
        out(i, 1) = sn * normals(i, 0) + cs * normals(i, 1);
    }
    return out;
}

Eigen::MatrixX3d rotateNormals(const Eigen::MatrixX3d &normals, const Eigen::MatrixX2d &turn)
{
    Eigen::MatrixX3d out = normals;
    for (Eigen::Index i = 0; i < normals.rows() && i < turn.rows(); ++i) {
        const double cs = turn(i, 0), sn = turn(i, 1);
        out(i, 0) = cs * normals(i, 0) - sn * normals(i, 1);
        out(i, 1) = sn * normals(i, 0) + cs * normals(i, 1);
    }
    return out;
}

} // namespace finbook::geometry
