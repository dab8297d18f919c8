// Typed errors of the geometry layer: a code the caller can branch on and a sentence for the
// user that names what is wrong with the input.
#pragma once

#include <string>

namespace finbook::geometry {

enum class GeometryErrorCode {
    EmptyInput,           // no strokes, or no finite point in any of them
    CoordinateOutOfRange, // |x| or |y| beyond kMaxCoordinate
    InvalidWidth,         // pen width negative, non-finite or beyond kMaxPenWidth
    InvalidOptions,       // option value negative, non-finite or out of its documented range
    TooManyPoints,        // more input points than kMaxInputPoints
    DegenerateRegion,     // the input covers no area (e.g. zero width and zero margin)
    NotSimple,            // a ring self-intersects or rings cross (meshRegion precondition)
    TriangulationFailed,  // CGAL or OpenMesh refused the region (reported, never thrown)
    ClippingFailed,       // Clipper refused the outlines or memory ran out (reported, not thrown)
    SkeletonFailed,       // CGAL's straight skeleton gave up on the outline (reported, not thrown)
    Cancelled,            // the caller's cancel callback asked to stop
    InvalidIndex,         // a joint, bone or part index that the skeleton does not have
    NonFiniteInput,       // NaN or infinity where every value is needed (cage corners)
    TooFewCorners,        // a cage with fewer than three distinct corners
    PointsOutsideCage,    // points that must lie inside a cage do not
    MalformedFile,        // a mesh file that does not follow its format (OFF)
};

struct GeometryError {
    GeometryErrorCode code;
    std::string message; // one sentence for the user: what happened and what to do
};

// Canvas coordinates are pixels; beyond this the drawing is surely corrupt, and the
// integer clipping stays exact (coordinates × 256 fit into 31 bits).
inline constexpr double kMaxCoordinate = 1.0e6;
inline constexpr double kMaxPenWidth = 1.0e4;
inline constexpr long kMaxInputPoints = 2'000'000;

} // namespace finbook::geometry
