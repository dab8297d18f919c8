#include <finbook/model/inbetween/spacing.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {

// The strongest favour bunches drawings like a cubic ease: t = u³ towards the first key.
constexpr double kMaxFavourExponent = 3.0;

double clamp01(double u)
{
    return std::isfinite(u) ? std::clamp(u, 0.0, 1.0) : 0.0;
}

} // namespace

double spacedTime(double u, const Spacing &spacing)
{
    u = clamp01(u);
    if (u == 0.0 || u == 1.0)
        return u; // the keys themselves, exactly
    switch (spacing.kind) {
    case SpacingKind::Linear:
        return u;
    case SpacingKind::EaseIn:
        return u * u;
    case SpacingKind::EaseOut:
        return 1.0 - (1.0 - u) * (1.0 - u);
    case SpacingKind::EaseInOut:
        return u * u * (3.0 - 2.0 * u);
    case SpacingKind::Favour: {
        const double f =
            std::isfinite(spacing.favour) ? std::clamp(spacing.favour, -1.0, 1.0) : 0.0;
        const double p = 1.0 + (kMaxFavourExponent - 1.0) * std::abs(f);
        return f <= 0.0 ? std::pow(u, p) : 1.0 - std::pow(1.0 - u, p);
    }
    }
    return u;
}

std::vector<double> inbetweenTimes(int count, const Spacing &spacing)
{
    std::vector<double> times;
    for (int i = 1; i <= count; ++i)
        times.push_back(spacedTime(double(i) / double(count + 1), spacing));
    return times;
}

} // namespace finbook::model
