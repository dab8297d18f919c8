// Spacing of in-betweens: where between two keys each generated drawing sits, like the
// spacing chart an animator pencils next to a key.
#pragma once

#include <vector>

namespace finbook::model {

// Names follow the usual curve-editor convention: "ease in" starts slowly (drawings bunched
// near the first key), "ease out" arrives slowly (bunched near the second key). Favour is the
// animator's "favour the first / second key" as one number.
enum class SpacingKind { Linear, EaseIn, EaseOut, EaseInOut, Favour };

struct Spacing {
    SpacingKind kind = SpacingKind::Linear;
    // For SpacingKind::Favour: -1 = bunched hard at the first key, 0 = even, +1 = bunched hard
    // at the second key. Clamped to -1..1; NaN counts as 0.
    double favour = 0.0;
};

// Maps even progress u (0..1) to the interpolation parameter t (0..1). Monotone; 0 → 0 and
// 1 → 1 exactly; u outside 0..1 (or NaN) is clamped (NaN → 0).
double spacedTime(double u, const Spacing &spacing);

// The t of `count` in-betweens strictly between two keys (u = i / (count + 1), i = 1..count),
// increasing. count < 1 gives none.
std::vector<double> inbetweenTimes(int count, const Spacing &spacing);

} // namespace finbook::model
