// The mouth chart's default drawings (swap/mouth_chart.h). Each mouth is built from a few
// curves in a unit box (x from -1 to 1 across the mouth, y down), scaled to the chart's width:
// an outline of the lips' opening, and teeth or a tongue where the shape shows them.
#include "../command_text.h"

#include <finbook/model/swap/mouth_chart.h>

#include <cmath>
#include <numbers>

namespace finbook::model {

namespace {
using Curve = std::vector<QPointF>;

// An ellipse (closed: its last point is its first) centred at (0, cy).
Curve ellipse(double rx, double ry, double cy = 0.0, int points = 40)
{
    Curve c;
    for (int i = 0; i <= points; ++i) {
        const double t = 2.0 * std::numbers::pi * i / points;
        c.emplace_back(rx * std::cos(t), cy + ry * std::sin(t));
    }
    return c;
}

// A lip line from (-w, y) to (w, y) bowed by `bow` (positive: down in the middle).
Curve bowed(double w, double y, double bow, int points = 16)
{
    Curve c;
    for (int i = 0; i <= points; ++i) {
        const double x = -w + 2.0 * w * i / points;
        const double u = x / w;
        c.emplace_back(x, y + bow * (1.0 - u * u));
    }
    return c;
}

// An open mouth's outline: upper lip from corner to corner, lower lip back (closed).
Curve opening(double w, double upper, double lower, int points = 20)
{
    Curve c = bowed(w, 0.0, -upper, points);
    const Curve low = bowed(w, 0.0, lower, points);
    for (auto it = low.rbegin() + 1; it != low.rend(); ++it)
        c.push_back(*it);
    return c;
}

std::vector<Curve> shapeCurves(int shape)
{
    switch (shape) {
    case 0: // A: M B P, lips pressed together
        return {bowed(0.8, 0.0, 0.06)};
    case 1: // B: most consonants, slightly open, teeth showing
        return {opening(0.85, 0.12, 0.2), bowed(0.6, 0.02, 0.03)};
    case 2: // C: EH AE, open
        return {opening(0.85, 0.2, 0.45)};
    case 3: // D: AA, wide open, tongue in the bottom
        return {opening(0.95, 0.3, 0.8), bowed(0.5, 0.55, -0.12)};
    case 4: // E: AO ER, slightly rounded
        return {ellipse(0.55, 0.4, 0.1)};
    case 5: // F: UW OW W, puckered
        return {ellipse(0.3, 0.3, 0.05), ellipse(0.12, 0.12, 0.05, 20)};
    case 6: // G: F V, upper teeth on the lower lip
        return {opening(0.8, 0.15, 0.12), bowed(0.55, 0.0, 0.08)};
    case 7: // H: L, open with the tongue up behind the teeth
        return {opening(0.85, 0.25, 0.55), bowed(0.45, 0.1, -0.2)};
    default: // X: rest, lips closed and relaxed
        return {bowed(0.7, 0.0, -0.04)};
    }
}

StrokeDataPtr stroke(const Curve &curve, QPointF centre, double scale, QRgb color, float width)
{
    auto data = std::make_shared<StrokeData>();
    data->color = color;
    data->width = width;
    for (const QPointF &p : curve)
        data->points.push_back(
            {float(centre.x() + scale * p.x()), float(centre.y() + scale * p.y()), 1.0f});
    return data;
}
} // namespace

QString mouthChartName(int shape)
{
    static const char *const names[] = {
        QT_TRANSLATE_NOOP("Command", "A (M B P)"), QT_TRANSLATE_NOOP("Command", "B (K S T)"),
        QT_TRANSLATE_NOOP("Command", "C (EH AE)"), QT_TRANSLATE_NOOP("Command", "D (AA)"),
        QT_TRANSLATE_NOOP("Command", "E (AO ER)"), QT_TRANSLATE_NOOP("Command", "F (UW OW W)"),
        QT_TRANSLATE_NOOP("Command", "G (F V)"),   QT_TRANSLATE_NOOP("Command", "H (L)"),
        QT_TRANSLATE_NOOP("Command", "X (rest)")};
    if (shape < 0 || shape > 8)
        return {};
    return Command::tr(names[shape]);
}

int mouthChartShape(const QString &drawingName)
{
    // By its letter, so a renamed "A (closed)" or an untranslated chart still keys.
    const QString trimmed = drawingName.trimmed();
    if (trimmed.isEmpty())
        return -1;
    const QChar letter = trimmed.front().toUpper();
    if (trimmed.size() > 1 && trimmed[1].isLetterOrNumber())
        return -1;
    if (letter >= QLatin1Char('A') && letter <= QLatin1Char('H'))
        return letter.unicode() - 'A';
    return letter == QLatin1Char('X') ? 8 : -1;
}

SwapSet mouthChart(Document &doc, QPointF centre, double width, QRgb color, float penWidth)
{
    SwapSet set;
    set.id = doc.allocateId();
    set.name = Command::tr("Mouth");
    const double scale = width / 2.0;
    for (int shape = 0; shape < 9; ++shape) {
        SwapDrawing d;
        d.id = doc.allocateId();
        d.name = mouthChartName(shape);
        for (const Curve &c : shapeCurves(shape))
            d.strokes.push_back(
                Stroke{doc.allocateId(), stroke(c, centre, scale, color, penWidth)});
        set.drawings.push_back(std::move(d));
    }
    return set;
}

} // namespace finbook::model
