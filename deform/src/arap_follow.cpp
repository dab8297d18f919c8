// Components without pins follow the nearest pinned component (issue 15): a leg or a tail
// drawn apart from the body is its own connected component; left at rest it would stay
// behind while the body moves. Each such component is attached at rest to the nearest vertex
// of a pinned component (its "anchor") and takes, after every solve, the anchor's
// displacement and the best rotation of the triangles around the anchor: a rigid motion, so
// the follower keeps its shape and its offset to the body.
#include "arap_solver.h"

#include <algorithm>
#include <limits>

namespace finbook::deform::detail {
namespace {

// Uniform grid over the candidate anchors for nearest-vertex queries: O(1) per query near the
// candidates; far queries stop as soon as no cell can beat the bound they are given.
class AnchorGrid {
public:
    AnchorGrid(const Eigen::VectorXcd &rest, std::vector<int> candidates)
        : m_rest(rest)
        , m_points(std::move(candidates))
    {
        m_low = m_high = rest(m_points.front());
        for (const int v : m_points) {
            m_low = {std::min(m_low.real(), rest(v).real()),
                     std::min(m_low.imag(), rest(v).imag())};
            m_high = {std::max(m_high.real(), rest(v).real()),
                      std::max(m_high.imag(), rest(v).imag())};
        }
        const double extent = std::max(m_high.real() - m_low.real(), m_high.imag() - m_low.imag());
        const int side = std::max(1, int(std::sqrt(double(m_points.size()))));
        m_cell = extent > 0.0 ? extent / side : 1.0;
        m_columns = std::clamp(int((m_high.real() - m_low.real()) / m_cell) + 1, 1, side + 1);
        m_rows = std::clamp(int((m_high.imag() - m_low.imag()) / m_cell) + 1, 1, side + 1);
        std::vector<int> start(std::size_t(m_columns * m_rows) + 1, 0);
        for (const int v : m_points)
            ++start[std::size_t(cellOf(rest(v))) + 1];
        for (std::size_t c = 1; c < start.size(); ++c)
            start[c] += start[c - 1];
        m_start = start;
        m_sorted.resize(m_points.size());
        for (const int v : m_points) // ascending vertex order within each cell
            m_sorted[std::size_t(start[std::size_t(cellOf(rest(v)))]++)] = v;
    }

    // Nearest candidate to q closer than sqrt(bound²) (lowest index on ties), or −1.
    int nearest(Complex q, double &boundSquared) const
    {
        const Complex clamped{std::clamp(q.real(), m_low.real(), m_high.real()),
                              std::clamp(q.imag(), m_low.imag(), m_high.imag())};
        const double outside = squaredMagnitude(q - clamped);
        const int cx = column(clamped), cy = row(clamped);
        int best = -1;
        for (int r = 0;; ++r) {
            const double reach = std::max(0, r - 1) * m_cell; // cells of ring r are this far
            if (outside + reach * reach > boundSquared || r > m_columns + m_rows)
                return best;
            for (int y = std::max(0, cy - r); y <= std::min(m_rows - 1, cy + r); ++y) {
                if (y == cy - r || y == cy + r) { // a whole row of the ring
                    for (int x = std::max(0, cx - r); x <= std::min(m_columns - 1, cx + r); ++x)
                        visit(y * m_columns + x, q, boundSquared, best);
                    continue;
                }
                if (cx - r >= 0) // else only its two ends
                    visit(y * m_columns + cx - r, q, boundSquared, best);
                if (cx + r < m_columns)
                    visit(y * m_columns + cx + r, q, boundSquared, best);
            }
        }
    }

private:
    int column(Complex p) const
    {
        return std::clamp(int((p.real() - m_low.real()) / m_cell), 0, m_columns - 1);
    }
    int row(Complex p) const
    {
        return std::clamp(int((p.imag() - m_low.imag()) / m_cell), 0, m_rows - 1);
    }
    int cellOf(Complex p) const { return row(p) * m_columns + column(p); }

    void visit(int cell, Complex q, double &boundSquared, int &best) const
    {
        for (int k = m_start[std::size_t(cell)]; k < m_start[std::size_t(cell) + 1]; ++k) {
            const int v = m_sorted[std::size_t(k)];
            const double distance = squaredMagnitude(m_rest(v) - q);
            if (distance < boundSquared || (distance == boundSquared && v < best)) {
                boundSquared = distance;
                best = v;
            }
        }
    }

    const Eigen::VectorXcd &m_rest;
    std::vector<int> m_points, m_start, m_sorted;
    Complex m_low, m_high;
    double m_cell = 1.0;
    int m_columns = 1, m_rows = 1;
};

} // namespace

void buildFollowers(const Eigen::VectorXi &componentLabel, const std::vector<bool> &pinned,
                    ArapPrecompute &d)
{
    // componentLabel and pinned are per internal vertex / per component.
    const Eigen::Index n = d.rest.size(), firstRigid = d.freeCount + d.handleEntry.size();
    d.rigidFollowGroup = Eigen::VectorXi::Constant(n - firstRigid, -1);
    std::vector<int> candidates;
    for (Eigen::Index v = 0; v < n; ++v)
        if (pinned[std::size_t(componentLabel(v))])
            candidates.push_back(int(v));
    if (!d.options.followNearestComponent || candidates.empty() ||
        Eigen::Index(candidates.size()) == n)
        return;
    const AnchorGrid grid(d.rest, std::move(candidates));
    std::vector<int> group(pinned.size(), -1), anchors;
    std::vector<double> bounds;
    for (Eigen::Index v = firstRigid; v < n; ++v) {
        const int component = componentLabel(v);
        if (pinned[std::size_t(component)])
            continue;
        if (group[std::size_t(component)] < 0) {
            group[std::size_t(component)] = int(anchors.size());
            anchors.push_back(-1);
            bounds.push_back(std::numeric_limits<double>::infinity());
        }
        const int g = group[std::size_t(component)];
        d.rigidFollowGroup(v - firstRigid) = g;
        double bound = bounds[std::size_t(g)];
        const int found = grid.nearest(d.rest(v), bound);
        if (found >= 0 && (bound < bounds[std::size_t(g)] || anchors[std::size_t(g)] < 0)) {
            bounds[std::size_t(g)] = bound;
            anchors[std::size_t(g)] = found;
        }
    }
    d.followAnchor =
        Eigen::Map<const Eigen::VectorXi>(anchors.data(), Eigen::Index(anchors.size()));
}

void placeFollowers(const ArapPrecompute &d, Eigen::VectorXcd &W)
{
    const Eigen::Index groups = d.followAnchor.size();
    if (groups == 0)
        return;
    const Eigen::Index solved = d.freeCount + d.handleEntry.size();
    Eigen::VectorXcd rotation = Eigen::VectorXcd::Ones(groups);
    for (Eigen::Index g = 0; g < groups; ++g) {
        const int a = d.followAnchor(g);
        if (a >= solved)
            continue; // the anchor's component only translates
        // One Procrustes fit over all corners of the anchor's triangles (sum of their
        // cross-covariances), so one distorted triangle cannot swing the follower.
        Complex s;
        for (int c = d.vertexStart(a); c < d.vertexStart(a + 1); ++c) {
            const int t = d.vertexTriangle(c);
            const Complex origin = W(d.triangles(t, 0));
            for (int k = 1; k < 3; ++k)
                s += mulConj(d.restCentered(t, k), W(d.triangles(t, k)) - origin);
        }
        const double length = std::sqrt(squaredMagnitude(s));
        if (length > 0.0 && std::isfinite(length))
            rotation(g) = s / length;
    }
    const Eigen::Index firstRigid = solved;
    for (Eigen::Index i = 0; i < d.rigidFollowGroup.size(); ++i) {
        const int g = d.rigidFollowGroup(i);
        if (g < 0)
            continue;
        const int a = d.followAnchor(g);
        W(firstRigid + i) = W(a) + mul(rotation(g), d.rest(firstRigid + i) - d.rest(a));
    }
}

} // namespace finbook::deform::detail
