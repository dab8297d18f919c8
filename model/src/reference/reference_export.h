// The reference under exported frames (ExportOptions::includeReference): its own media (an
// export runs on a worker, beside the canvas's decoder), the picture at each plan entry's
// time on the document's timeline. Private to the model's export.
#pragma once

#include <finbook/model/export/export_plan.h>
#include <finbook/model/reference/reference_media.h>

namespace finbook::model {

class ExportReference {
public:
    // Empty (nothing painted) unless options.includeReference and the source has a visible
    // reference whose media decodes.
    ExportReference(const ExportSource &source, const ExportOptions &options);
    bool isEmpty() const { return !m_media; }
    // A sentence when the reference was asked for but cannot be used (its media does not
    // decode, or passes the limits); empty otherwise.
    const QString &problem() const { return m_problem; }
    const Reference &reference() const { return m_reference; }
    // The picture under document frame `frameIndex`; null when empty.
    QImage picture(int frameIndex) const;

private:
    Reference m_reference;
    std::shared_ptr<ReferenceMedia> m_media;
    std::vector<qint64> m_startTicks; // per document frame
    int m_fps = 12;
    QString m_problem;
};

} // namespace finbook::model
