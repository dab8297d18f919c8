// Clipping triangles to a super-level set of a piecewise linear function (shade/shading.h).
#include <finbook/geometry/shade/shading.h>

#include <cmath>

namespace finbook::geometry {

Pieces superLevelPieces(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                        const Eigen::VectorXd &value, double threshold)
{
    Pieces out;
    out.points.reserve(std::size_t(F.rows()) * 3);
    out.starts.reserve(std::size_t(F.rows()) + 1);
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        Eigen::Vector2d p[3];
        double s[3];
        bool finite = true;
        int above = 0;
        for (int k = 0; k < 3; ++k) {
            const int v = F(f, k);
            if (v < 0 || v >= V.rows() || v >= value.size()) {
                finite = false;
                break;
            }
            p[k] = V.row(v).transpose();
            s[k] = value(v);
            finite = finite && p[k].allFinite() && std::isfinite(s[k]);
            above += s[k] >= threshold ? 1 : 0;
        }
        if (!finite || above == 0)
            continue;
        if (above == 3) {
            out.points.insert(out.points.end(), {p[0], p[1], p[2]});
        } else {
            // Sutherland–Hodgman against one half-space, in the triangle's corner order.
            for (int k = 0; k < 3; ++k) {
                const int n = (k + 1) % 3;
                const bool in = s[k] >= threshold, nextIn = s[n] >= threshold;
                if (in)
                    out.points.push_back(p[k]);
                if (in != nextIn) {
                    const double t = (threshold - s[k]) / (s[n] - s[k]);
                    out.points.push_back(p[k] + t * (p[n] - p[k]));
                }
            }
        }
        out.starts.push_back(int(out.points.size()));
    }
    return out;
}

} // namespace finbook::geometry
