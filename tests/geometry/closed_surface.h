// Shared by the tests of inflated solids and the 3D exports (OBJ, glTF): whether triangles,
// as index triples, make a closed and consistently oriented surface.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace finbook::test {

// Every directed edge is used exactly once, and its reverse exactly once; no triangles is no
// surface.
inline bool closedAndOriented(const std::vector<std::array<int, 3>> &faces)
{
    std::map<std::pair<int, int>, int> directed;
    for (const auto &f : faces)
        for (int c = 0; c < 3; ++c)
            ++directed[{f[std::size_t(c)], f[std::size_t((c + 1) % 3)]}];
    for (const auto &[edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            return false;
    }
    return !faces.empty();
}

} // namespace finbook::test
