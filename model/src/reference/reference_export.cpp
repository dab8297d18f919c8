#include "reference_export.h"

#include <QCoreApplication>

#include <algorithm>

namespace finbook::model {

ExportReference::ExportReference(const ExportSource &source, const ExportOptions &options)
    : m_reference(source.reference)
    , m_fps(source.settings.fps)
{
    if (!options.includeReference || m_reference.isEmpty() || !m_reference.visible ||
        m_reference.opacity <= 0.0)
        return;
    auto media = ReferenceMedia::open(m_reference);
    if (!media) {
        m_problem = QCoreApplication::translate("Export", "The reference \"%1\" is left out: %2")
                        .arg(m_reference.name, media.error());
        return;
    }
    m_media = *media;
    // A few frames: an export walks forward, so the decoder seldom seeks.
    m_media->setCacheLimit(qint64(64) << 20);
    qint64 tick = 0;
    m_startTicks.reserve(source.frames.size());
    for (const Frame &f : source.frames) {
        m_startTicks.push_back(tick);
        tick += std::max(1, f.hold);
    }
}

QImage ExportReference::picture(int frameIndex) const
{
    if (!m_media || frameIndex < 0 || std::size_t(frameIndex) >= m_startTicks.size())
        return {};
    return m_media->frame(
        m_media->frameAtTick(m_reference, m_startTicks[std::size_t(frameIndex)], m_fps));
}

} // namespace finbook::model
