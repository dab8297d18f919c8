// The 3D model export as glTF 2.0 binary, read back by the test's own reader of the container
// (header, JSON chunk, BIN chunk), of the JSON (with Qt's parser, not the writer's code) and of
// the buffers: every view and accessor lies inside the buffer, positions agree with their
// min/max and with the solids the model makes, normals are unit and point outwards, each mesh
// is closed, consistently oriented and of positive volume, and colours are the objects' export
// colours made linear, as glTF defines baseColorFactor.
#include "solid_export_support.h"

#include <finbook/geometry/inflate/glb_writer.h>
#include <finbook/model/export/frame_solids.h>

#include <QTemporaryDir>
#include <QtTest>

#include <cstring>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::test;

namespace {

struct GlbMesh {
    std::string name;
    std::vector<std::array<float, 3>> positions, normals;
    std::vector<std::array<int, 3>> faces;
    std::array<double, 4> colour{};
    bool blended = false;
    std::vector<std::array<float, 2>> uv; // TEXCOORD_0, when it has one
    QImage texture;                       // its material's baseColorTexture, decoded
};

struct Glb {
    QJsonObject json;
    std::vector<GlbMesh> meshes; // in scene node order
    QString problem;
};

quint32 u32At(const QByteArray &bytes, qsizetype at)
{
    quint32 value = 0;
    std::memcpy(&value, bytes.constData() + at, 4);
    return value;
}

// The bytes of accessor `index` (its view's slice), checking it lies inside `bin`.
bool accessorBytes(const QJsonObject &json, const QByteArray &bin, int index, int componentType,
                   const char *type, QByteArray &out, qint64 &count)
{
    const QJsonObject accessor = json[QStringLiteral("accessors")].toArray().at(index).toObject();
    if (accessor[QStringLiteral("componentType")].toInt() != componentType ||
        accessor[QStringLiteral("type")].toString() != QLatin1String(type))
        return false;
    const QJsonObject view = json[QStringLiteral("bufferViews")]
                                 .toArray()
                                 .at(accessor[QStringLiteral("bufferView")].toInt())
                                 .toObject();
    const qint64 offset = view[QStringLiteral("byteOffset")].toInteger();
    const qint64 length = view[QStringLiteral("byteLength")].toInteger();
    count = accessor[QStringLiteral("count")].toInteger();
    const qint64 width = QLatin1String(type) == QLatin1String("VEC3")   ? 12
                         : QLatin1String(type) == QLatin1String("VEC2") ? 8
                                                                        : 4;
    if (offset % 4 != 0 || offset < 0 || offset + length > bin.size() || count * width > length)
        return false;
    out = bin.mid(offset, count * width);
    return true;
}

Glb parseGlb(const QByteArray &bytes)
{
    Glb glb;
    if (bytes.size() < 20 || !bytes.startsWith("glTF") || u32At(bytes, 4) != 2 ||
        u32At(bytes, 8) != quint32(bytes.size())) {
        glb.problem = QStringLiteral("bad header");
        return glb;
    }
    const quint32 jsonLength = u32At(bytes, 12);
    if (bytes.mid(16, 4) != "JSON" || jsonLength % 4 != 0 ||
        20 + jsonLength > quint32(bytes.size())) {
        glb.problem = QStringLiteral("bad JSON chunk");
        return glb;
    }
    QJsonParseError error;
    glb.json = QJsonDocument::fromJson(bytes.mid(20, jsonLength), &error).object();
    if (error.error != QJsonParseError::NoError) {
        glb.problem = error.errorString();
        return glb;
    }
    QByteArray bin;
    const qsizetype binAt = 20 + jsonLength;
    if (binAt < bytes.size()) {
        const quint32 binLength = u32At(bytes, binAt);
        if (bytes.mid(binAt + 4, 4) != QByteArray("BIN\0", 4) || binLength % 4 != 0 ||
            binAt + 8 + binLength != quint32(bytes.size())) {
            glb.problem = QStringLiteral("bad BIN chunk");
            return glb;
        }
        bin = bytes.mid(binAt + 8, binLength);
        const qint64 declared = glb.json[QStringLiteral("buffers")]
                                    .toArray()
                                    .at(0)[QStringLiteral("byteLength")]
                                    .toInteger();
        if (declared > bin.size() || declared + 3 < bin.size()) {
            glb.problem =
                QStringLiteral("buffer length %1 for a chunk of %2").arg(declared).arg(bin.size());
            return glb;
        }
    }
    const QJsonArray nodes = glb.json[QStringLiteral("nodes")].toArray();
    for (const QJsonValue sceneNode :
         glb.json[QStringLiteral("scenes")].toArray().at(0)[QStringLiteral("nodes")].toArray()) {
        const QJsonObject node = nodes.at(sceneNode.toInt()).toObject();
        const QJsonObject mesh = glb.json[QStringLiteral("meshes")]
                                     .toArray()
                                     .at(node[QStringLiteral("mesh")].toInt())
                                     .toObject();
        const QJsonObject primitive = mesh[QStringLiteral("primitives")].toArray().at(0).toObject();
        const QJsonObject attributes = primitive[QStringLiteral("attributes")].toObject();
        GlbMesh out;
        out.name = node[QStringLiteral("name")].toString().toStdString();
        QByteArray p, n, f;
        qint64 vertices = 0, normals = 0, indices = 0;
        if (primitive[QStringLiteral("mode")].toInt(4) != 4 ||
            !accessorBytes(glb.json, bin, attributes[QStringLiteral("POSITION")].toInt(), 5126,
                           "VEC3", p, vertices) ||
            !accessorBytes(glb.json, bin, attributes[QStringLiteral("NORMAL")].toInt(), 5126,
                           "VEC3", n, normals) ||
            !accessorBytes(glb.json, bin, primitive[QStringLiteral("indices")].toInt(), 5125,
                           "SCALAR", f, indices) ||
            normals != vertices || indices % 3 != 0) {
            glb.problem =
                QStringLiteral("bad accessors of %1").arg(QString::fromStdString(out.name));
            return glb;
        }
        out.positions.resize(std::size_t(vertices));
        out.normals.resize(std::size_t(vertices));
        out.faces.resize(std::size_t(indices / 3));
        std::memcpy(out.positions.data(), p.constData(), std::size_t(p.size()));
        std::memcpy(out.normals.data(), n.constData(), std::size_t(n.size()));
        std::vector<quint32> raw(static_cast<std::size_t>(indices));
        std::memcpy(raw.data(), f.constData(), std::size_t(f.size()));
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] >= quint32(vertices)) {
                glb.problem = QStringLiteral("index %1 of %2 vertices").arg(raw[i]).arg(vertices);
                return glb;
            }
            out.faces[i / 3][i % 3] = int(raw[i]);
        }
        // The accessor's min and max are exactly those of the data.
        const QJsonObject position = glb.json[QStringLiteral("accessors")]
                                         .toArray()
                                         .at(attributes[QStringLiteral("POSITION")].toInt())
                                         .toObject();
        for (int c = 0; c < 3; ++c) {
            float lo = out.positions.front()[std::size_t(c)], hi = lo;
            for (const auto &v : out.positions) {
                lo = std::min(lo, v[std::size_t(c)]);
                hi = std::max(hi, v[std::size_t(c)]);
            }
            // As a double, the way validators read JSON numbers: the float's exact value.
            if (position[QStringLiteral("min")].toArray().at(c).toDouble() != double(lo) ||
                position[QStringLiteral("max")].toArray().at(c).toDouble() != double(hi))
                glb.problem = QStringLiteral("min/max of %1").arg(QString::fromStdString(out.name));
        }
        const QJsonObject material = glb.json[QStringLiteral("materials")]
                                         .toArray()
                                         .at(primitive[QStringLiteral("material")].toInt())
                                         .toObject();
        const QJsonArray factor = material[QStringLiteral("pbrMetallicRoughness")]
                                      .toObject()[QStringLiteral("baseColorFactor")]
                                      .toArray();
        for (int c = 0; c < 4; ++c)
            out.colour[std::size_t(c)] = factor.at(c).toDouble(-1);
        out.blended = material[QStringLiteral("alphaMode")].toString() == QLatin1String("BLEND");
        if (attributes.contains(QStringLiteral("TEXCOORD_0"))) {
            QByteArray t;
            qint64 count = 0;
            if (!accessorBytes(glb.json, bin, attributes[QStringLiteral("TEXCOORD_0")].toInt(),
                               5126, "VEC2", t, count) ||
                count != vertices) {
                glb.problem = QStringLiteral("bad texture coordinates");
                return glb;
            }
            out.uv.resize(std::size_t(count));
            std::memcpy(out.uv.data(), t.constData(), std::size_t(t.size()));
        }
        const QJsonObject textureRef = material[QStringLiteral("pbrMetallicRoughness")]
                                           .toObject()[QStringLiteral("baseColorTexture")]
                                           .toObject();
        if (!textureRef.isEmpty()) {
            const QJsonObject texture = glb.json[QStringLiteral("textures")]
                                            .toArray()
                                            .at(textureRef[QStringLiteral("index")].toInt())
                                            .toObject();
            const QJsonObject image = glb.json[QStringLiteral("images")]
                                          .toArray()
                                          .at(texture[QStringLiteral("source")].toInt())
                                          .toObject();
            const QJsonObject view = glb.json[QStringLiteral("bufferViews")]
                                         .toArray()
                                         .at(image[QStringLiteral("bufferView")].toInt())
                                         .toObject();
            const qint64 offset = view[QStringLiteral("byteOffset")].toInteger();
            const qint64 length = view[QStringLiteral("byteLength")].toInteger();
            if (image[QStringLiteral("mimeType")].toString() != QLatin1String("image/png") ||
                offset < 0 || offset + length > bin.size() ||
                !glb.json[QStringLiteral("samplers")]
                     .toArray()
                     .at(texture[QStringLiteral("sampler")].toInt())
                     .isObject()) {
                glb.problem = QStringLiteral("bad texture");
                return glb;
            }
            out.texture = QImage::fromData(bin.mid(offset, length), "PNG");
        }
        glb.meshes.push_back(std::move(out));
    }
    return glb;
}

double volumeOf(const GlbMesh &mesh)
{
    double volume = 0;
    for (const auto &f : mesh.faces) {
        const auto &a = mesh.positions[std::size_t(f[0])], &b = mesh.positions[std::size_t(f[1])],
                   &c = mesh.positions[std::size_t(f[2])];
        volume += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
                   double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
                   double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
                  6.0;
    }
    return volume;
}

// Share of vertices whose normal is unit (within 1e-4) and agrees in direction with the area-
// weighted normal of the triangles around it.
double outwardUnitNormals(const GlbMesh &mesh)
{
    std::vector<std::array<double, 3>> around(mesh.positions.size(), {0, 0, 0});
    for (const auto &f : mesh.faces) {
        const auto &a = mesh.positions[std::size_t(f[0])], &b = mesh.positions[std::size_t(f[1])],
                   &c = mesh.positions[std::size_t(f[2])];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        for (int i : f)
            for (int k = 0; k < 3; ++k)
                around[std::size_t(i)][std::size_t(k)] += n[k];
    }
    int good = 0;
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const auto &n = mesh.normals[i];
        const double length =
            std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        const double dot = n[0] * around[i][0] + n[1] * around[i][1] + n[2] * around[i][2];
        good += std::abs(length - 1.0) < 1e-4 && dot > 0;
    }
    return mesh.normals.empty() ? 0.0 : double(good) / double(mesh.normals.size());
}

double linear(int srgb8)
{
    const double c = srgb8 / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

bool linearColour(const std::array<double, 4> &factor, QRgb expected)
{
    return std::abs(factor[0] - linear(qRed(expected))) < 1e-6 &&
           std::abs(factor[1] - linear(qGreen(expected))) < 1e-6 &&
           std::abs(factor[2] - linear(qBlue(expected))) < 1e-6 &&
           std::abs(factor[3] - qAlpha(expected) / 255.0) < 1e-6;
}

ExportOptions glbOptions(const QString &target)
{
    ExportOptions o;
    o.format = ExportFormat::Glb;
    o.target = target;
    return o;
}

void checkSolid(const GlbMesh &mesh, const geometry::InflatedSolid &solid)
{
    QCOMPARE(long(mesh.positions.size()), long(solid.V.rows()));
    QCOMPARE(long(mesh.faces.size()), long(solid.F.rows()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        for (int c = 0; c < 3; ++c)
            QCOMPARE(mesh.positions[i][std::size_t(c)], float(solid.V(Eigen::Index(i), c)));
    QVERIFY2(closedAndOriented(mesh.faces), mesh.name.c_str());
    const double volume = volumeOf(mesh);
    QVERIFY2(volume > 0, mesh.name.c_str());
    QVERIFY(std::abs(volume - geometry::signedVolume(solid)) < 1e-3 * volume);
    QVERIFY2(outwardUnitNormals(mesh) > 0.99, mesh.name.c_str());
}
} // namespace

class TestExportGlb : public QObject {
    Q_OBJECT
private slots:
    void generatedFrameRoundTrips();
    void exampleFrameIsClosedSolids();
    void namesColoursAndOpacity();
    void nothingMeshableWritesNothing();
    void existingFileIsRefusedWithoutOverwrite();
    void cancelLeavesNothing();
    void picturesAreTexturedSolids();
};

void TestExportGlb::generatedFrameRoundTrips()
{
    QTemporaryDir dir;
    const ExportSource source = generatedSource();
    const QString target = dir.filePath(QStringLiteral("scene.glb"));
    QCOMPARE(exportFormatForPath(target), std::optional(ExportFormat::Glb));
    const auto result = exportAnimation(source, glbOptions(target));
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QCOMPARE(result->files, QStringList({target}));
    QCOMPARE(result->fileCount, qint64(1));
    QVERIFY2(result->note.contains(QLatin1String("2 object")), qPrintable(result->note));
    QCOMPARE(filesIn(dir.path()), QStringList({"scene.glb"}));

    const Glb glb = parseGlb(readAll(target));
    QVERIFY2(glb.problem.isEmpty(), qPrintable(glb.problem));
    QCOMPARE(glb.json[QStringLiteral("asset")][QStringLiteral("version")].toString(),
             QStringLiteral("2.0"));
    QCOMPARE(glb.meshes.size(), std::size_t(3));
    // glTF keeps names as they are: repeated ones, spaces.
    QCOMPARE(glb.meshes[0].name, std::string("Body"));
    QCOMPARE(glb.meshes[1].name, std::string("Left arm"));
    QCOMPARE(glb.meshes[2].name, std::string("Body"));
    const auto solids = frameSolids(source.frames.front(), source.settings);
    QVERIFY(solids && solids->objects.size() == 3);
    for (std::size_t i = 0; i < 3; ++i)
        checkSolid(glb.meshes[i], solids->objects[i].solid);
    QVERIFY(linearColour(glb.meshes[0].colour, kBlue));
    QVERIFY(linearColour(glb.meshes[1].colour, kGreen));
    QVERIFY(linearColour(glb.meshes[2].colour, 0xff000000));
    QVERIFY(!glb.meshes[0].blended);

    // The same frame as OBJ holds the same solids: the two formats differ only in encoding.
    const QString obj = dir.filePath(QStringLiteral("scene.obj"));
    ExportOptions objOptions = glbOptions(obj);
    objOptions.format = ExportFormat::Obj;
    QVERIFY(exportAnimation(source, objOptions));
    QCOMPARE(readAll(obj).count("\nv "),
             qsizetype(glb.meshes[0].positions.size() + glb.meshes[1].positions.size() +
                       glb.meshes[2].positions.size()));
}

void TestExportGlb::exampleFrameIsClosedSolids()
{
    const ExportSource source = loadExample();
    QVERIFY(!source.frames.empty());
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("walk.glb"));
    const auto result = exportAnimation(source, glbOptions(target));
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    const Glb glb = parseGlb(readAll(target));
    QVERIFY2(glb.problem.isEmpty(), qPrintable(glb.problem));
    const Frame &frame = source.frames[std::size_t(std::max(0, source.settings.playStart))];
    const auto solids = frameSolids(frame, source.settings);
    QVERIFY(solids && !solids->objects.empty());
    QCOMPARE(glb.meshes.size(), solids->objects.size());
    for (std::size_t i = 0; i < glb.meshes.size(); ++i) {
        checkSolid(glb.meshes[i], solids->objects[i].solid);
        QVERIFY(linearColour(glb.meshes[i].colour, solids->objects[i].color));
    }
    qInfo("walk.finbook frame 1 as glTF: %zu meshes, %lld bytes", glb.meshes.size(),
          QFileInfo(target).size());
}

void TestExportGlb::namesColoursAndOpacity()
{
    // The writer on its own: a name with JSON's special characters and CJK text, a half-
    // transparent colour, and an object with no triangles (left out).
    const auto solids = frameSolids(generatedSource().frames.front(), DocumentSettings{});
    QVERIFY(solids && !solids->objects.empty());
    const geometry::InflatedSolid &solid = solids->objects.front().solid;
    const std::string name = "Arm \"left\"\\\n\xe8\x85\x95"; // …\n腕
    const std::string bytes =
        geometry::glbBytes({{name, solid, 1.0, 0.5, 0.0, 0.5, {}},
                            {"empty", geometry::InflatedSolid{}, 0, 0, 0, 1, {}}});
    const Glb glb = parseGlb(QByteArray::fromStdString(bytes));
    QVERIFY2(glb.problem.isEmpty(), qPrintable(glb.problem));
    QCOMPARE(glb.meshes.size(), std::size_t(1));
    QCOMPARE(glb.meshes[0].name, name);
    QVERIFY(glb.meshes[0].blended);
    QVERIFY(std::abs(glb.meshes[0].colour[0] - 1.0) < 1e-12);
    QVERIFY(std::abs(glb.meshes[0].colour[1] - 0.21404114048223255) < 1e-9); // sRGB 0.5
    QCOMPARE(glb.meshes[0].colour[2], 0.0);
    QCOMPARE(glb.meshes[0].colour[3], 0.5);

    // Nothing to hold: still a valid file, with an empty scene and no buffer.
    const Glb none = parseGlb(QByteArray::fromStdString(geometry::glbBytes({})));
    QVERIFY2(none.problem.isEmpty(), qPrintable(none.problem));
    QVERIFY(none.meshes.empty());
    QVERIFY(!none.json.contains(QStringLiteral("buffers")));
}

void TestExportGlb::nothingMeshableWritesNothing()
{
    ExportSource source = generatedSource();
    Frame &frame = source.frames.front();
    frame.groups.erase(frame.groups.begin(), frame.groups.begin() + 3);
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("out"));
    const auto result = exportAnimation(source, glbOptions(folder + QStringLiteral("/dot.glb")));
    QVERIFY(!result);
    QCOMPARE(result.error().code, ExportErrorCode::BadOptions);
    QVERIFY2(result.error().message.contains(QLatin1String("can be made 3D")),
             qPrintable(result.error().message));
    QVERIFY(!QFileInfo::exists(folder));
}

void TestExportGlb::existingFileIsRefusedWithoutOverwrite()
{
    const ExportSource source = generatedSource();
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("scene.glb"));
    QFile old(target);
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write("old");
    old.close();
    const auto refused = exportAnimation(source, glbOptions(target));
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, ExportErrorCode::TargetExists);
    QCOMPARE(readAll(target), QByteArray("old"));
    QCOMPARE(existingExportTargets(source, glbOptions(target)), QStringList({target}));
    ExportOptions overwrite = glbOptions(target);
    overwrite.overwrite = true;
    QVERIFY(exportAnimation(source, overwrite));
    QVERIFY(readAll(target).startsWith("glTF"));
    QCOMPARE(filesIn(dir.path()), QStringList({"scene.glb"}));
}

void TestExportGlb::cancelLeavesNothing()
{
    const ExportSource source = generatedSource();
    QTemporaryDir dir;
    int calls = 0;
    const auto result = exportAnimation(source, glbOptions(dir.filePath(QStringLiteral("c.glb"))),
                                        [&calls](qint64, qint64) { return ++calls < 2; });
    QVERIFY(!result);
    QCOMPARE(result.error().code, ExportErrorCode::Cancelled);
    QCOMPARE(filesIn(dir.path()), QStringList());
}

void TestExportGlb::picturesAreTexturedSolids()
{
    // A posed picture object: a closed solid where the picture shows, textured with it.
    Id id = kNoId;
    const ExportSource source = pictureSource(&id);
    const StrokeGroup &group = source.frames.front().groups.back();
    QCOMPARE(group.id, id);
    QVERIFY(group.isDeformed() && !group.deformed->pictureVertices.empty());
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("painted.glb"));
    const auto result = exportAnimation(source, glbOptions(target));
    QVERIFY2(result.hasValue(), qPrintable(result ? QString() : result.error().message));
    const Glb glb = parseGlb(readAll(target));
    QVERIFY2(glb.problem.isEmpty(), qPrintable(glb.problem));
    QCOMPARE(glb.meshes.size(), std::size_t(1));
    const GlbMesh &mesh = glb.meshes.front();
    QCOMPARE(mesh.name, std::string("Painted"));
    QVERIFY(volumeOf(mesh) > 0.0);
    QVERIFY(outwardUnitNormals(mesh) > 0.95);
    QVERIFY(mesh.blended);
    // The picture itself, pixel for pixel, and a texture coordinate per vertex inside it.
    const QImage picture =
        group.picture->data->image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    QCOMPARE(mesh.texture.convertToFormat(QImage::Format_ARGB32_Premultiplied), picture);
    QCOMPARE(mesh.uv.size(), mesh.positions.size());
    for (const auto &t : mesh.uv)
        QVERIFY(t[0] >= -1e-6f && t[0] <= 1.0f + 1e-6f && t[1] >= -1e-6f && t[1] <= 1.0f + 1e-6f);
    // The texture mesh's own vertices come first, each where the pose shows it (y up) and
    // mapped to its own place in the picture.
    const Eigen::MatrixX2d &uv = group.picture->mesh->uv;
    const std::vector<QPointF> &posed = group.deformed->pictureVertices;
    QVERIFY(mesh.positions.size() > posed.size());
    double worstPlace = 0.0, worstTexel = 0.0, moved = 0.0;
    const Eigen::MatrixX2d rest = group.picture->restVertices();
    for (std::size_t i = 0; i < posed.size(); ++i) {
        const auto &p = mesh.positions[i];
        worstPlace =
            std::max({worstPlace, std::abs(p[0] - posed[i].x()), std::abs(-p[1] - posed[i].y())});
        worstTexel = std::max(
            {worstTexel, std::abs(mesh.uv[i][0] * picture.width() - uv(Eigen::Index(i), 0)),
             std::abs(mesh.uv[i][1] * picture.height() - uv(Eigen::Index(i), 1))});
        moved = std::max(moved, std::hypot(posed[i].x() - rest(Eigen::Index(i), 0),
                                           posed[i].y() - rest(Eigen::Index(i), 1)));
    }
    QVERIFY2(worstPlace < 1e-3, qPrintable(QString::number(worstPlace)));
    QVERIFY2(worstTexel < 1e-3, qPrintable(QString::number(worstTexel)));
    QVERIFY(moved > 20.0); // the pose is not the rest
}

QTEST_GUILESS_MAIN(TestExportGlb)
#include "tst_export_glb.moc"
