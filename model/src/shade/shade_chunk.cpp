// Reading an object's "shad" chunk and the "lite" section (layouts in finbook_file_format.h).
// Both are ancillary: an older Finbook skips them and shows flat fills under the default light.
#include "../finbook_file_reader.h"

#include <cmath>

namespace finbook::model::file_format {

void Reader::readShadingChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the fill shading list");
    const quint32 n = c.count(2, what);
    if (n != g.fills.size())
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the object shades %1 fills but has %2").arg(n).arg(g.fills.size()));
    std::vector<FillShading> shading(n);
    for (FillShading &s : shading) {
        const quint8 ramp = c.u8(what);
        const quint8 rim = c.u8(what);
        if (ramp > kLastShadeRamp || rim > 1)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("a fill's shading (%1, %2) is not one Finbook knows")
                       .arg(ramp)
                       .arg(rim));
        s.ramp = ShadeRamp(ramp);
        s.rim = rim != 0;
    }
    for (std::size_t i = 0; i < shading.size(); ++i)
        g.fills[i].shading = shading[i];
}

void Reader::readLightSection(Cursor &c)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the light");
    const double azimuth = c.f64(what);
    const double elevation = c.f64(what);
    c.expectEnd(what);
    if (!(azimuth >= 0.0 && azimuth < 360.0) || !(elevation >= 0.0 && elevation <= 90.0))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the light's direction (%1°, %2°) is outside 0 to 360° and 0 to "
                               "90°")
                   .arg(azimuth)
                   .arg(elevation));
    m_doc.settings.lightAzimuth = azimuth;
    m_doc.settings.lightElevation = elevation;
}

} // namespace finbook::model::file_format
