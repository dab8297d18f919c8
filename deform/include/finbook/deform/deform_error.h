// Typed failures shared by the deformers (ARAP, cages, skeletons). The model layer turns
// them into sentences for the user; nothing here ever returns NaN instead of an error.
#pragma once

#include <finbook/geometry/expected.h>

#include <string>
#include <vector>

namespace finbook::deform {

enum class DeformErrorCode {
    EmptyMesh,            // no vertices or no triangles
    InvalidIndex,         // a triangle or pin refers to a vertex that does not exist
    NonFiniteInput,       // NaN or infinity in rest positions or pin targets
    CoordinateOutOfRange, // |coordinate| beyond kMaxDeformCoordinate (squares would overflow)
    DegenerateTriangle,   // zero-area triangle or a triangle repeating a vertex
    NonManifoldVertex,    // two fans of triangles meet only at a vertex (split it first)
    SizeMismatch,         // targets do not match the pins the precompute was made for
    FactorizationFailed,  // sparse Cholesky refused a matrix that should be SPD
    SolveFailed,          // a solve produced non-finite values or a large residual
    Cancelled,            // the caller's cancellation callback returned true
    InvalidSkeleton,      // no joints, a parent out of range, or a cycle in the joint tree
    InvalidCage,          // fewer than 3 corners, self-crossing, zero area (geometry's message)
    MeshingFailed,        // the cage's interior could not be meshed
    PointsOutsideCage,    // points to bind lie outside the cage (DeformError::items lists them)
    TooLarge,             // the mesh and coordinates asked for would not fit in memory
};

// Far beyond any canvas, far below the square root of the largest double: the deformers
// square coordinate differences, so larger input could overflow to infinity.
inline constexpr double kMaxDeformCoordinate = 1e100;

struct DeformError {
    DeformErrorCode code;
    std::string message;
    // The rows of the input the error is about, ascending, when it concerns some of them
    // (points outside the cage, non-finite points); empty otherwise.
    std::vector<int> items = {};
};

} // namespace finbook::deform
