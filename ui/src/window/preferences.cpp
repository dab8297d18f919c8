#include <finbook/model/types.h>
#include <finbook/ui/window/preferences.h>

#include <QSettings>

#include <algorithm>

namespace finbook::ui {

Preferences Preferences::load(QSettings &settings)
{
    Preferences p;
    settings.beginGroup(QStringLiteral("preferences"));
    OnionSkin &o = p.onionSkin;
    o.enabled = settings.value(QStringLiteral("onion/enabled"), o.enabled).toBool();
    o.before = std::clamp(settings.value(QStringLiteral("onion/before"), o.before).toInt(), 0, 5);
    o.after = std::clamp(settings.value(QStringLiteral("onion/after"), o.after).toInt(), 0, 5);
    o.opacity =
        std::clamp(settings.value(QStringLiteral("onion/opacity"), o.opacity).toDouble(), 0.0, 1.0);
    const QColor before(settings.value(QStringLiteral("onion/beforeTint")).toString());
    const QColor after(settings.value(QStringLiteral("onion/afterTint")).toString());
    if (before.isValid())
        o.beforeTint = before;
    if (after.isValid())
        o.afterTint = after;
    p.frameRate = std::clamp(settings.value(QStringLiteral("frameRate"), p.frameRate).toInt(),
                             model::kMinFps, model::kMaxFps);
    const QSize size = settings.value(QStringLiteral("canvasSize"), p.canvasSize).toSize();
    p.canvasSize = QSize(std::clamp(size.width(), 1, model::kMaxCanvasSide),
                         std::clamp(size.height(), 1, model::kMaxCanvasSide));
    p.autosaveMinutes = std::clamp(
        settings.value(QStringLiteral("autosaveMinutes"), p.autosaveMinutes).toInt(), 0, 60);
    settings.endGroup();
    return p;
}

void Preferences::save(QSettings &settings) const
{
    settings.beginGroup(QStringLiteral("preferences"));
    settings.setValue(QStringLiteral("onion/enabled"), onionSkin.enabled);
    settings.setValue(QStringLiteral("onion/before"), onionSkin.before);
    settings.setValue(QStringLiteral("onion/after"), onionSkin.after);
    settings.setValue(QStringLiteral("onion/opacity"), onionSkin.opacity);
    settings.setValue(QStringLiteral("onion/beforeTint"), onionSkin.beforeTint.name());
    settings.setValue(QStringLiteral("onion/afterTint"), onionSkin.afterTint.name());
    settings.setValue(QStringLiteral("frameRate"), frameRate);
    settings.setValue(QStringLiteral("canvasSize"), canvasSize);
    settings.setValue(QStringLiteral("autosaveMinutes"), autosaveMinutes);
    settings.endGroup();
}

} // namespace finbook::ui
