// A contact sheet of inflated shapes for `finbook-bench inflate --sheet`: each shape's
// normals lit by one light from the upper left, smooth and as three cel tones side by side.
#pragma once

#include <finbook/geometry/inflate/inflation.h>

#include <QImage>
#include <QString>

#include <vector>

namespace finbook::bench {

class InflateSheet {
public:
    void add(const geometry::Inflation &inflation, const QString &label);
    bool save(const QString &path) const;

private:
    std::vector<QImage> m_tiles;
};

} // namespace finbook::bench
