// The pen's stabiliser: a "lazy string" (pulled string), as Lazy Nezumi and Procreate's
// StreamLine pull ink. The ink point hangs on a string of a given length behind the cursor: it
// stays put while the cursor moves within the string's reach, and when the cursor pulls the
// string taut the ink follows along the string, so it never comes nearer than the string's
// length. Jitter smaller than the string never reaches the ink, and a wobbly path comes out as
// the smooth curve the string drags along it. Pressure is smoothed with the position: each step
// of the ink takes the cursor's pressure by the share the step is of the step plus the string.
//
// Length 0 is no stabiliser at all: the ink is the cursor, every event, with no lag. When the
// pen lifts the ink catches up, so a stroke always ends exactly where the pen lifted (and starts
// where it touched down). Nothing here remembers more than the ink point: an event costs a few
// floating-point operations whatever the stroke's length.
#pragma once

#include <finbook/model/types.h>

#include <optional>

namespace finbook::ui {

class LazyString {
public:
    // `length` in canvas pixels (the string's reach); negative or non-finite counts as 0.
    explicit LazyString(double length = 0.0);
    double length() const { return m_length; }

    // The pen touched down at `first`: the ink starts there (and is the stroke's first point).
    void start(const model::StrokePoint &first);
    // The cursor moved to `cursor`: the ink's new place when the string pulled it, else nothing.
    std::optional<model::StrokePoint> follow(const model::StrokePoint &cursor);
    // The pen lifted at `last`: the ink catches up to it (the stroke's last point).
    model::StrokePoint finish(const model::StrokePoint &last);

    const model::StrokePoint &ink() const { return m_ink; }

private:
    double m_length = 0.0;
    model::StrokePoint m_ink{};
};

// The string's length in canvas pixels for a stabiliser strength (0..10) at a view zoom: 4 screen
// pixels per step, so the hand feels the same pull at any zoom.
double stabiliserLength(int strength, double zoom);

} // namespace finbook::ui
