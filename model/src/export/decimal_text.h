// Internal: numbers as the text formats (SVG, Lottie) write them, short and exact.
#pragma once

#include <QByteArray>

#include <algorithm>
#include <cmath>

namespace finbook::model {

// `value` rounded to `decimals` places (0..6), trailing zeros dropped: "12.5", "3", "-0.25".
// Non-finite values are written as 0, and values are clamped to ±`largest` (which must stay
// far from where llround overflows) before rounding.
inline void appendDecimal(QByteArray &out, double value, int decimals, double largest)
{
    if (!std::isfinite(value))
        value = 0.0;
    value = std::clamp(value, -largest, largest);
    long long unit = 1;
    for (int i = 0; i < decimals; ++i)
        unit *= 10;
    const long long scaled = std::llround(value * double(unit));
    if (scaled < 0)
        out += '-';
    const long long magnitude = std::llabs(scaled);
    out += QByteArray::number(magnitude / unit);
    long long fraction = magnitude % unit;
    if (fraction == 0)
        return;
    int digits = decimals;
    while (fraction % 10 == 0) {
        fraction /= 10;
        --digits;
    }
    out += '.' + QByteArray::number(fraction).rightJustified(digits, '0');
}

} // namespace finbook::model
