// A paint device of a given size that hands QPainter a test's own paint engine (one that
// records or counts what it is asked to draw), with a plain 96-dpi, 32-bit screen's metrics.
#pragma once

#include <QPaintDevice>
#include <QSize>

namespace engine_test {

template <class Engine> class EngineDevice : public QPaintDevice {
public:
    explicit EngineDevice(QSize size)
        : m_size(size)
    {}
    QPaintEngine *paintEngine() const override { return &m_engine; }
    Engine &engine() { return m_engine; }

protected:
    int metric(PaintDeviceMetric metric) const override
    {
        switch (metric) {
        case PdmWidth:
            return m_size.width();
        case PdmHeight:
            return m_size.height();
        case PdmDpiX:
        case PdmDpiY:
        case PdmPhysicalDpiX:
        case PdmPhysicalDpiY:
            return 96;
        case PdmDevicePixelRatio:
            return 1;
        case PdmDevicePixelRatioScaled:
            return int(QPaintDevice::devicePixelRatioFScale());
        case PdmDepth:
            return 32;
        default:
            return 0;
        }
    }

private:
    QSize m_size;
    mutable Engine m_engine;
};

} // namespace engine_test
