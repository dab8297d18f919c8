#include "split_chords.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace finbook::geometry::inflate_detail {
namespace {

using Edge = std::pair<int, int>;

Edge undirected(int a, int b)
{
    return a < b ? Edge(a, b) : Edge(b, a);
}

} // namespace

int splitOutlineChords(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F)
{
    std::vector<Edge> directed;
    directed.reserve(std::size_t(F.rows()) * 3);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            directed.emplace_back(F(f, k), F(f, (k + 1) % 3));
    std::sort(directed.begin(), directed.end());
    const auto has = [&](int a, int b) {
        return std::binary_search(directed.begin(), directed.end(), Edge(a, b));
    };
    std::vector<char> onOutline(std::size_t(V.rows()), 0);
    for (const auto &[a, b] : directed)
        if (!has(b, a))
            onOutline[std::size_t(a)] = onOutline[std::size_t(b)] = 1;
    std::vector<Edge> chords;
    for (const auto &[a, b] : directed)
        if (a < b && onOutline[std::size_t(a)] && onOutline[std::size_t(b)] && has(b, a))
            chords.emplace_back(a, b);
    if (chords.empty())
        return 0;
    std::sort(chords.begin(), chords.end());
    chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
    const Eigen::Index n = V.rows();
    V.conservativeResize(n + Eigen::Index(chords.size()), 2);
    for (std::size_t c = 0; c < chords.size(); ++c)
        V.row(n + Eigen::Index(c)) = 0.5 * (V.row(chords[c].first) + V.row(chords[c].second));
    const auto midpoint = [&](int a, int b) {
        const auto it = std::lower_bound(chords.begin(), chords.end(), undirected(a, b));
        return it != chords.end() && *it == undirected(a, b) ? int(n + (it - chords.begin())) : -1;
    };
    std::vector<std::array<int, 3>> faces;
    faces.reserve(std::size_t(F.rows()) + 3 * chords.size());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        // Rotate so the split edges come first, then fan from the corners and midpoints.
        std::array<int, 3> v{F(f, 0), F(f, 1), F(f, 2)};
        std::array<int, 3> m{midpoint(v[0], v[1]), midpoint(v[1], v[2]), midpoint(v[2], v[0])};
        const int splits = int(std::count_if(m.begin(), m.end(), [](int x) { return x >= 0; }));
        if (splits == 0) {
            faces.push_back(v);
            continue;
        }
        if (splits == 3) {
            faces.push_back({v[0], m[0], m[2]});
            faces.push_back({v[1], m[1], m[0]});
            faces.push_back({v[2], m[2], m[1]});
            faces.push_back({m[0], m[1], m[2]});
            continue;
        }
        // One or two splits: rotate until edge 0 is split and, for two, edge 1 too if possible.
        for (int r = 0; r < 3 && !(m[0] >= 0 && (splits == 1 || m[1] >= 0)); ++r) {
            std::rotate(v.begin(), v.begin() + 1, v.end());
            std::rotate(m.begin(), m.begin() + 1, m.end());
        }
        if (splits == 1) {
            faces.push_back({v[0], m[0], v[2]});
            faces.push_back({m[0], v[1], v[2]});
        } else {
            faces.push_back({v[0], m[0], v[2]});
            faces.push_back({m[0], v[1], m[1]});
            faces.push_back({m[0], m[1], v[2]});
        }
    }
    F.resize(Eigen::Index(faces.size()), 3);
    for (std::size_t f = 0; f < faces.size(); ++f)
        F.row(Eigen::Index(f)) << faces[f][0], faces[f][1], faces[f][2];
    return int(chords.size());
}

} // namespace finbook::geometry::inflate_detail
