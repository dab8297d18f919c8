// Cages for the cage tests: convex, concave and strongly concave polygons (corners c×2,
// positive shoelace area unless reversed), in canvas-sized pixel coordinates.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace finbook::test {

inline Eigen::MatrixX2d squareCage(double size = 200.0)
{
    Eigen::MatrixX2d c(4, 2);
    c << 0, 0, size, 0, size, size, 0, size;
    return c;
}

// A 270° arc band, outer radius r, inner r/2, `perArc` corners on each arc: the concave cage
// the notes measured mean value coordinates on (−0.037 at 16 corners per arc).
inline Eigen::MatrixX2d horseshoeCage(int perArc = 16, double r = 200.0)
{
    Eigen::MatrixX2d c(2 * perArc, 2);
    const double a0 = -0.75 * M_PI, a1 = 0.75 * M_PI;
    for (int i = 0; i < perArc; ++i) {
        const double a = a0 + (a1 - a0) * i / (perArc - 1);
        c.row(i) << r * std::cos(a), r * std::sin(a);
        const double b = a1 - (a1 - a0) * i / (perArc - 1);
        c.row(perArc + i) << 0.5 * r * std::cos(b), 0.5 * r * std::sin(b);
    }
    return c;
}

// A band of half-width w around the spiral r = r0 + k θ, θ ∈ [0, turns·2π]: deep, winding
// concavity (successive turns 2πk apart).
inline Eigen::MatrixX2d spiralCage(double turns = 1.5, int samples = 40, double r0 = 30.0,
                                   double k = 20.0, double w = 9.0)
{
    Eigen::MatrixX2d c(2 * samples, 2);
    for (int i = 0; i < samples; ++i) {
        const double t = turns * 2.0 * M_PI * i / (samples - 1);
        const double r = r0 + k * t;
        c.row(i) << (r + w) * std::cos(t), (r + w) * std::sin(t);
        const double s = turns * 2.0 * M_PI * (samples - 1 - i) / (samples - 1);
        const double q = r0 + k * s;
        c.row(samples + i) << (q - w) * std::cos(s), (q - w) * std::sin(s);
    }
    return c;
}

// A palm with five fingers (thumb to the side): 24 corners, right angles only.
inline Eigen::MatrixX2d handCage()
{
    const std::vector<std::pair<double, double>> p = {
        {0, 0},     {120, 0},  {120, 60}, {160, 70}, {160, 90}, {120, 90}, {120, 120}, {110, 120},
        {110, 210}, {90, 210}, {90, 120}, {80, 120}, {80, 230}, {60, 230}, {60, 120},  {50, 120},
        {50, 220},  {30, 220}, {30, 120}, {20, 120}, {20, 190}, {0, 190},  {0, 120},   {-5, 60}};
    Eigen::MatrixX2d c(Eigen::Index(p.size()), 2);
    for (std::size_t i = 0; i < p.size(); ++i)
        c.row(Eigen::Index(i)) << p[i].first, p[i].second;
    return c;
}

// A star with `spikes` tips at radius r and notches at inner × r: sharp corners (5° at the
// defaults), where the mesher cannot reach its 20° bound.
inline Eigen::MatrixX2d starCage(int spikes = 12, double inner = 0.15, double r = 200.0)
{
    Eigen::MatrixX2d c(2 * spikes, 2);
    for (int i = 0; i < 2 * spikes; ++i) {
        const double a = M_PI * i / spikes, radius = i % 2 == 0 ? r : inner * r;
        c.row(i) << radius * std::cos(a), radius * std::sin(a);
    }
    return c;
}

inline Eigen::MatrixX2d reversedCage(const Eigen::MatrixX2d &c)
{
    return c.colwise().reverse();
}

struct NamedCage {
    std::string name;
    Eigen::MatrixX2d corners;
};

// The strongly concave ones, where mean value coordinates go negative.
inline std::vector<NamedCage> concaveCages()
{
    return {{"horseshoe", horseshoeCage()}, {"spiral", spiralCage()}, {"hand", handCage()}};
}

inline std::vector<NamedCage> allCages()
{
    std::vector<NamedCage> cages = concaveCages();
    cages.push_back({"square", squareCage()});
    cages.push_back({"horseshoe reversed", reversedCage(horseshoeCage())});
    cages.push_back({"coarse horseshoe", horseshoeCage(4)});
    cages.push_back({"sharp star", starCage()});
    return cages;
}

} // namespace finbook::test
