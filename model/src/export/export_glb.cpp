// The 3D model export as glTF 2.0 binary: one frame's objects inflated to closed solids
// (frame_solids.h), each a named node and mesh in its export colour (a picture object textured
// with its picture, embedded), in one self-contained .glb file (geometry/inflate/glb_writer.h).
// Written the safe way the other single files are: locked, written beside the target, synced and
// renamed into place only when complete.
#include "export_formats.h"
#include "export_text.h"

#include <finbook/geometry/inflate/glb_writer.h>
#include <finbook/model/picture/picture_object.h>

#include <QColor>
#include <QFileInfo>

namespace finbook::model {

namespace {
QByteArray glbFile(const FrameSolids &solids)
{
    std::vector<geometry::GlbObject> objects;
    objects.reserve(solids.objects.size());
    for (std::size_t i = 0; i < solids.objects.size(); ++i) {
        const ObjectSolid &object = solids.objects[i];
        const QString name = object.name.trimmed().isEmpty()
                                 ? QStringLiteral("object_%1").arg(i + 1)
                                 : object.name.trimmed();
        const QColor colour = QColor::fromRgba(object.color);
        objects.push_back({name.toStdString(), object.solid, colour.redF(), colour.greenF(),
                           colour.blueF(), colour.alphaF(),
                           object.picture ? object.picture->png.toStdString() : std::string()});
    }
    return QByteArray::fromStdString(geometry::glbBytes(objects));
}
} // namespace

ExportOutcome exportGlb(const ExportContext &context)
{
    std::optional<FrameSolids> made;
    const auto written =
        writeSingleFile(context.options, [&]() -> Expected<QByteArray, ExportError> {
            auto solids = exportedSolids(context);
            if (!solids)
                return unexpected(solids.error());
            QByteArray bytes = glbFile(*solids);
            if (bytes.isEmpty())
                return unexpected(exportError(
                    ExportErrorCode::BadOptions,
                    Export::tr(
                        "Frame %1 makes a 3D model larger than a glTF file can hold (4 GiB); "
                        "export it as OBJ instead.")
                        .arg(context.plan.frames.front() + 1)));
            made = std::move(*solids);
            return bytes;
        });
    if (written)
        return unexpected(*written);
    return modelResult(context, {context.options.target}, *made);
}

} // namespace finbook::model
