// Typed failures shared by the deformers (ARAP, cages, skeletons). The model layer turns
// them into sentences for the user; nothing here ever returns NaN instead of an error.
#pragma once

#include <finbook/geometry/expected.h>

#include <string>

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
};

// Far beyond any canvas, far below the square root of the largest double: the deformers
// square coordinate differences, so larger input could overflow to infinity.
inline constexpr double kMaxDeformCoordinate = 1e100;

struct DeformError {
    DeformErrorCode code;
    std::string message;
};

} // namespace finbook::deform
