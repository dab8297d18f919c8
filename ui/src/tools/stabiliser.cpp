#include <finbook/ui/tools/stabiliser.h>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
constexpr double kScreenPixelsPerStep = 4.0;
}

LazyString::LazyString(double length)
    : m_length(std::isfinite(length) ? std::max(0.0, length) : 0.0)
{}

void LazyString::start(const model::StrokePoint &first)
{
    m_ink = first;
}

std::optional<model::StrokePoint> LazyString::follow(const model::StrokePoint &cursor)
{
    if (m_length <= 0.0) {
        m_ink = cursor;
        return cursor;
    }
    const double dx = double(cursor.x) - m_ink.x, dy = double(cursor.y) - m_ink.y;
    const double reach = std::hypot(dx, dy);
    if (!(reach > m_length)) // slack (or not finite): the ink stays
        return std::nullopt;
    const double step = reach - m_length; // the ink moves along the string until it is taut
    const double t = step / reach;
    const double share = step / (step + m_length);
    m_ink.x = float(m_ink.x + t * dx);
    m_ink.y = float(m_ink.y + t * dy);
    m_ink.pressure = float(m_ink.pressure + share * (double(cursor.pressure) - m_ink.pressure));
    return m_ink;
}

model::StrokePoint LazyString::finish(const model::StrokePoint &last)
{
    m_ink = last;
    return last;
}

double stabiliserLength(int strength, double zoom)
{
    if (strength <= 0 || !(zoom > 0.0) || !std::isfinite(zoom))
        return 0.0;
    return kScreenPixelsPerStep * std::min(strength, 10) / zoom;
}

} // namespace finbook::ui
