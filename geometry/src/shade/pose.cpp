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
    w.index = Eigen::MatrixXi::Constant(points.rows(), std::max(kk, 1), -1);
    w.weight = Eigen::MatrixXd::Zero(points.rows(), std::max(kk, 1));
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
            w.index(i, j) = heap[std::size_t(j)].second;
            w.weight(i, j) = weight;
            total += weight;
        }
        for (int j = 0; j < int(heap.size()); ++j) {
            w.weight(i, j) /= total;
            centroid += w.weight(i, j) * controls.row(w.index(i, j));
        }
        w.offset.row(i) = p - centroid;
    }
    return w;
}

PosedPoints applyPose(const PoseWeights &weights, const Eigen::MatrixX2d &posed)
{
    const Eigen::Index n = weights.offset.rows();
    PosedPoints out;
    out.V.resize(n, 2);
    out.angle = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        Eigen::Vector2d restCentroid = Eigen::Vector2d::Zero(), shownCentroid = restCentroid;
        bool any = false;
        const auto shown = [&](int c) -> Eigen::Vector2d {
            const bool ok = c < posed.rows() && posed.row(c).allFinite();
            return ok ? Eigen::Vector2d(posed.row(c).transpose())
                      : Eigen::Vector2d(weights.rest.row(c).transpose());
        };
        for (Eigen::Index j = 0; j < weights.index.cols(); ++j) {
            const int c = weights.index(i, j);
            if (c < 0)
                continue;
            any = true;
            restCentroid += weights.weight(i, j) * weights.rest.row(c).transpose();
            shownCentroid += weights.weight(i, j) * shown(c);
        }
        const Eigen::Vector2d offset = weights.offset.row(i).transpose();
        if (!any) {
            out.V.row(i) = offset.transpose(); // no control: the offset is the point itself
            continue;
        }
        double a = 0.0, b = 0.0;
        for (Eigen::Index j = 0; j < weights.index.cols(); ++j) {
            const int c = weights.index(i, j);
            if (c < 0)
                continue;
            const Eigen::Vector2d p = weights.rest.row(c).transpose() - restCentroid;
            const Eigen::Vector2d q = shown(c) - shownCentroid;
            a += weights.weight(i, j) * p.dot(q);
            b += weights.weight(i, j) * (p.x() * q.y() - p.y() * q.x());
        }
        const double angle = (a == 0.0 && b == 0.0) ? 0.0 : std::atan2(b, a);
        const double cs = std::cos(angle), sn = std::sin(angle);
        out.angle(i) = angle;
        out.V(i, 0) = shownCentroid.x() + cs * offset.x() - sn * offset.y();
        out.V(i, 1) = shownCentroid.y() + sn * offset.x() + cs * offset.y();
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

} // namespace finbook::geometry
