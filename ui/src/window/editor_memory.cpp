#include <finbook/ui/window/editor_memory.h>

#include <QSettings>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
const QString kGroup = QStringLiteral("editor");
} // namespace

EditorMemory EditorMemory::load(QSettings &settings)
{
    EditorMemory m;
    settings.beginGroup(kGroup);
    const QColor color(settings.value(QStringLiteral("pen/color")).toString());
    if (color.isValid())
        m.pen.color = color;
    bool ok = false;
    const double width = settings.value(QStringLiteral("pen/width")).toDouble(&ok);
    if (ok && std::isfinite(width))
        m.pen.width = std::clamp(width, PenTool::kMinWidth, PenTool::kMaxWidth);
    const int smoothing = settings.value(QStringLiteral("pen/smoothing")).toInt(&ok);
    if (ok)
        m.pen.smoothing = std::clamp(smoothing, 0, PenTool::kMaxSmoothing);
    const int stabiliser = settings.value(QStringLiteral("pen/stabiliser")).toInt(&ok);
    if (ok)
        m.pen.stabiliser = std::clamp(stabiliser, 0, PenTool::kMaxStabiliser);
    m.pen.pressure = settings.value(QStringLiteral("pen/pressure"), true).toBool();
    m.tool = settings.value(QStringLiteral("tool")).toString();
    settings.endGroup();
    return m;
}

void EditorMemory::save(QSettings &settings) const
{
    settings.beginGroup(kGroup);
    settings.setValue(QStringLiteral("pen/color"), pen.color.name(QColor::HexArgb));
    settings.setValue(QStringLiteral("pen/width"), pen.width);
    settings.setValue(QStringLiteral("pen/smoothing"), pen.smoothing);
    settings.setValue(QStringLiteral("pen/stabiliser"), pen.stabiliser);
    settings.setValue(QStringLiteral("pen/pressure"), pen.pressure);
    settings.setValue(QStringLiteral("tool"), tool);
    settings.endGroup();
}

} // namespace finbook::ui
