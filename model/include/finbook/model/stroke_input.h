// A stroke as the geometry layer's outline, region and shape code take it.
#pragma once

#include <finbook/geometry/stroke_input.h>
#include <finbook/model/types.h>

#include <cmath>
#include <vector>

namespace finbook::model {

// The points' centre line with the pen width; a width the pen cannot have (NaN, 0 or less,
// from a damaged file) outlines as 1 px.
inline geometry::StrokeInput strokeInput(const std::vector<StrokePoint> &points, double width)
{
    geometry::StrokeInput in;
    in.points.resize(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        in.points.row(Eigen::Index(i)) << points[i].x, points[i].y;
    in.width = std::isfinite(width) && width > 0 ? width : 1.0;
    return in;
}

} // namespace finbook::model
