// Fixtures of the Between Drawings tests and bench: drawings as a mesh plus stroke samples
// with normals, and the deformations that make key B from key A.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace finbook::test {

// Points along strokes with their unit normals (k×2 each).
struct StrokePoints {
    Eigen::MatrixX2d P;
    Eigen::MatrixX2d N;

    void add(const Eigen::Vector2d &p, const Eigen::Vector2d &n)
    {
        P.conservativeResize(P.rows() + 1, 2);
        N.conservativeResize(N.rows() + 1, 2);
        P.row(P.rows() - 1) = p.transpose();
        N.row(N.rows() - 1) = n.normalized().transpose();
    }
    // The segment a→b sampled every `spacing` (a included, b excluded), normal to its left.
    void addSegment(const Eigen::Vector2d &a, const Eigen::Vector2d &b, double spacing)
    {
        const Eigen::Vector2d d = b - a;
        const int steps = std::max(1, int(std::round(d.norm() / spacing)));
        const Eigen::Vector2d normal(-d.y(), d.x());
        for (int i = 0; i < steps; ++i)
            add(a + d * (double(i) / steps), normal);
    }
    // Outline of the axis-aligned rectangle [lo, hi], counter-clockwise from lo.
    void addRectangle(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double spacing)
    {
        const Eigen::Vector2d c1(hi.x(), lo.y()), c3(lo.x(), hi.y());
        addSegment(lo, c1, spacing);
        addSegment(c1, hi, spacing);
        addSegment(hi, c3, spacing);
        addSegment(c3, lo, spacing);
    }
    StrokePoints transformed(const Eigen::Matrix2d &linear, const Eigen::Vector2d &shift) const
    {
        StrokePoints out;
        out.P = (P * linear.transpose()).rowwise() + shift.transpose();
        out.N = N * linear.transpose();
        out.N.rowwise().normalize();
        return out;
    }
};

inline Eigen::Matrix2d rotationBy(double degrees)
{
    return Eigen::Rotation2Dd(degrees * std::numbers::pi / 180.0).toRotationMatrix();
}

// The bend of an arm along x: points right of the elbow turn by `degrees` about it.
struct ElbowBend {
    Eigen::Vector2d elbow;
    double degrees = 60.0;
    Eigen::Vector2d apply(const Eigen::Vector2d &p) const
    {
        return p.x() <= elbow.x() ? p : Eigen::Vector2d(elbow + rotationBy(degrees) * (p - elbow));
    }
    Eigen::Vector2d applyNormal(const Eigen::Vector2d &p, const Eigen::Vector2d &n) const
    {
        return p.x() <= elbow.x() ? n : Eigen::Vector2d(rotationBy(degrees) * n);
    }
};

// A strip along x (centre line y = midY) bent round into an arc over [start, start + length]
// by `degrees` in total; left of it unchanged, right of it carried on straight (rigidly).
struct StripCurl {
    double start = 100.0, length = 200.0, degrees = 240.0, midY = 20.0;
    double curvature() const { return degrees * std::numbers::pi / 180.0 / length; }
    double angleAt(double x) const { return std::clamp(x - start, 0.0, length) * curvature(); }
    Eigen::Vector2d apply(const Eigen::Vector2d &p) const
    {
        const double k = curvature(), phi = angleAt(p.x());
        const double along = p.x() - std::clamp(p.x(), start, start + length);
        const Eigen::Vector2d centre(start + std::sin(phi) / k, midY + (1.0 - std::cos(phi)) / k);
        return centre + (p.y() - midY) * Eigen::Vector2d(-std::sin(phi), std::cos(phi)) +
               along * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    }
};

} // namespace finbook::test
