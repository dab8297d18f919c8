// Reference placement and timing: the pure functions of reference.h.
#include <finbook/model/reference/reference.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

QTransform referenceTransform(const Reference &reference)
{
    QTransform t;
    t.translate(reference.center.x(), reference.center.y());
    t.rotate(reference.rotation);
    t.scale(reference.scale, reference.scale);
    t.translate(-reference.mediaSize.width() / 2, -reference.mediaSize.height() / 2);
    return t;
}

void fitReferenceToCanvas(Reference &reference, QSizeF canvas)
{
    reference.center = QPointF(canvas.width() / 2, canvas.height() / 2);
    reference.rotation = 0.0;
    const QSizeF media = reference.mediaSize;
    if (media.isEmpty() || canvas.isEmpty()) {
        reference.scale = 1.0;
        return;
    }
    const double fit = std::min(canvas.width() / media.width(), canvas.height() / media.height());
    reference.scale = std::clamp(fit, kMinReferenceScale, kMaxReferenceScale);
}

double referenceSeconds(const Reference &reference, qint64 tick, int fps)
{
    const double rate = reference.rate > 0.0 ? reference.rate : double(std::max(1, fps));
    return double(std::max<qint64>(0, tick)) / rate;
}

bool referenceValuesValid(const Reference &r)
{
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(r.center.x()) || !finite(r.center.y()) || !finite(r.scale) || !finite(r.rotation) ||
        !finite(r.opacity) || !finite(r.rate) || !finite(r.mediaSize.width()) ||
        !finite(r.mediaSize.height()))
        return false;
    return std::abs(r.center.x()) <= kMaxReferenceCoordinate &&
           std::abs(r.center.y()) <= kMaxReferenceCoordinate && r.scale >= kMinReferenceScale &&
           r.scale <= kMaxReferenceScale && std::abs(r.rotation) <= 360.0 && r.opacity >= 0.0 &&
           r.opacity <= 1.0 && r.rate >= 0.0 && r.rate <= kMaxReferenceRate &&
           r.mediaSize.width() >= 0.0 && r.mediaSize.width() <= 16384.0 &&
           r.mediaSize.height() >= 0.0 && r.mediaSize.height() <= 16384.0;
}

} // namespace finbook::model
