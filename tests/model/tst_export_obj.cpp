// The 3D model export (OBJ + MTL): a generated frame and the bundled example, read back by a
// small independent parser. Every object is a closed, consistently oriented solid of positive
// volume in its own material of the right colour; posed objects are exported as they show;
// objects that cannot be inflated are left out and counted; the files reach the target as the
// other formats' do (refused when in the way, nothing written on an error or a cancel).
#include "solid_export_support.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/export/frame_solids.h>

#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <map>
#include <numeric>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::test;

namespace {
struct ParsedObject {
    std::string name, group, material;
    std::vector<std::array<int, 3>> faces; // 0-based, into ParsedObj::v
    int firstVertex = 0, vertices = 0;
};

struct ParsedObj {
    std::string library;
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<double, 2>> vt;
    long normals = 0;
    long texturedCorners = 0; // face corners "a/b/c" with a texture index b equal to a
    std::vector<ParsedObject> objects;
    QString problem;
};

ParsedObj parseObj(const QByteArray &text)
{
    ParsedObj obj;
    for (const QByteArray &raw : text.split('\n')) {
        const QByteArray line = raw.trimmed();
        if (line.isEmpty() || line.startsWith('#'))
            continue;
        const QList<QByteArray> words = line.split(' ');
        const QByteArray tag = words.front();
        const std::string rest = line.mid(tag.size() + 1).toStdString();
        if (tag == "mtllib") {
            obj.library = rest;
        } else if (tag == "o") {
            obj.objects.push_back({rest, {}, {}, {}, int(obj.v.size()), 0});
        } else if (obj.objects.empty()) {
            obj.problem = QString::fromUtf8(line);
        } else if (tag == "g") {
            obj.objects.back().group = rest;
        } else if (tag == "usemtl") {
            obj.objects.back().material = rest;
        } else if (tag == "v" && words.size() == 4) {
            obj.v.push_back({words[1].toDouble(), words[2].toDouble(), words[3].toDouble()});
            ++obj.objects.back().vertices;
        } else if (tag == "vn" && words.size() == 4) {
            ++obj.normals;
        } else if (tag == "vt" && words.size() == 3) {
            obj.vt.push_back({words[1].toDouble(), words[2].toDouble()});
        } else if (tag == "f" && words.size() == 4) {
            std::array<int, 3> f{};
            for (int c = 0; c < 3; ++c) {
                const QList<QByteArray> parts = words[c + 1].split('/');
                f[std::size_t(c)] = parts.front().toInt() - 1;
                obj.texturedCorners +=
                    parts.size() == 3 && !parts[1].isEmpty() && parts[1] == parts[0];
            }
            obj.objects.back().faces.push_back(f);
        } else {
            obj.problem = QString::fromUtf8(line);
        }
    }
    return obj;
}

// newmtl name → Kd and d.
std::map<std::string, std::array<double, 4>> parseMtl(const QByteArray &text)
{
    std::map<std::string, std::array<double, 4>> materials;
    std::string current;
    for (const QByteArray &raw : text.split('\n')) {
        const QList<QByteArray> words = raw.trimmed().split(' ');
        if (words.front() == "newmtl" && words.size() == 2) {
            current = words[1].toStdString();
            materials[current] = {-1, -1, -1, 1};
        } else if (words.front() == "Kd" && words.size() == 4) {
            for (int c = 0; c < 3; ++c)
                materials[current][std::size_t(c)] = words[c + 1].toDouble();
        } else if (words.front() == "d" && words.size() == 2) {
            materials[current][3] = words[1].toDouble();
        }
    }
    return materials;
}

double volumeOf(const ParsedObj &obj, const ParsedObject &object)
{
    double volume = 0;
    for (const auto &f : object.faces) {
        const auto &a = obj.v[std::size_t(f[0])], &b = obj.v[std::size_t(f[1])],
                   &c = obj.v[std::size_t(f[2])];
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) /
                  6.0;
    }
    return volume;
}

bool faceIndicesInside(const ParsedObject &object)
{
    for (const auto &f : object.faces)
        for (int i : f)
            if (i < object.firstVertex || i >= object.firstVertex + object.vertices)
                return false;
    return true;
}

ExportOptions objOptions(const QString &target)
{
    ExportOptions o;
    o.format = ExportFormat::Obj;
    o.target = target;
    return o;
}

bool nearColour(const std::array<double, 4> &kd, QRgb expected)
{
    return std::abs(kd[0] - qRed(expected) / 255.0) < 1e-6 &&
           std::abs(kd[1] - qGreen(expected) / 255.0) < 1e-6 &&
           std::abs(kd[2] - qBlue(expected) / 255.0) < 1e-6;
}
} // namespace

class TestExportObj : public QObject {
    Q_OBJECT
private slots:
    void generatedFrameRoundTrips();
    void exampleFrameIsClosedSolids();
    void frameOptionPicksTheDrawing();
    void nothingMeshableWritesNothing();
    void armOverTheBodyExportsAsTwoSolids();
    void existingFilesAreRefusedWithoutOverwrite();
    void cameraFramesTheModel();
    void failedObjPutsTheOldMaterialsBack();
    void cancelLeavesNothing();
    void materialFileName_data();
    void materialFileName();
    void picturesAreTexturedSolids();
};

// Through the camera (issue 46), the model is the shot: a camera zoomed 2× on a circle puts
// it at the shot's centre (y up), twice as wide, twice as thick; without it, on the page.
void TestExportObj::cameraFramesTheModel()
{
    QTemporaryDir dir;
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    doc.undoStack()->push(new AddStrokeCommand(&doc, doc.frameAt(0).groups.at(0).id,
                                               circleStroke(QPointF(300, 200), 60, kBlue)));
    CameraKey k;
    k.center = QPointF(300, 200);
    k.zoom = 2.0;
    doc.undoStack()->push(setCameraKeyCommand(&doc, k).release());
    const QSizeF page(doc.settings().canvasSize);
    const auto extent = [](const ParsedObj &obj) {
        std::array<double, 6> box{1e9, -1e9, 1e9, -1e9, 1e9, -1e9};
        for (const auto &v : obj.v)
            for (int c = 0; c < 3; ++c) {
                box[std::size_t(2 * c)] = std::min(box[std::size_t(2 * c)], v[std::size_t(c)]);
                box[std::size_t(2 * c + 1)] =
                    std::max(box[std::size_t(2 * c + 1)], v[std::size_t(c)]);
            }
        return box;
    };
    ExportOptions options = objOptions(dir.filePath(QStringLiteral("page.obj")));
    options.camera = false;
    QVERIFY(exportAnimation(exportSource(doc), options));
    const auto onPage = extent(parseObj(readAll(options.target)));
    options = objOptions(dir.filePath(QStringLiteral("shot.obj")));
    const auto result = exportAnimation(exportSource(doc), options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    const auto inShot = extent(parseObj(readAll(options.target)));
    const auto mid = [](const std::array<double, 6> &b, int axis) {
        return (b[std::size_t(2 * axis)] + b[std::size_t(2 * axis + 1)]) / 2;
    };
    const auto size = [](const std::array<double, 6> &b, int axis) {
        return b[std::size_t(2 * axis + 1)] - b[std::size_t(2 * axis)];
    };
    QVERIFY2(std::abs(mid(onPage, 0) - 300) < 1 && std::abs(mid(onPage, 1) + 200) < 1,
             qPrintable(QStringLiteral("%1 %2").arg(mid(onPage, 0)).arg(mid(onPage, 1))));
    QVERIFY2(std::abs(mid(inShot, 0) - page.width() / 2) < 1.5 &&
                 std::abs(mid(inShot, 1) + page.height() / 2) < 1.5,
             qPrintable(QStringLiteral("%1 %2").arg(mid(inShot, 0)).arg(mid(inShot, 1))));
    for (int axis = 0; axis < 3; ++axis)
        QVERIFY2(std::abs(size(inShot, axis) / size(onPage, axis) - 2.0) < 0.02,
                 qPrintable(QStringLiteral("axis %1: %2 vs %3")
                                .arg(axis)
                                .arg(size(inShot, axis))
                                .arg(size(onPage, axis))));
}

void TestExportObj::generatedFrameRoundTrips()
{
    QTemporaryDir dir;
    Id posedId = kNoId;
    const ExportSource source = generatedSource(&posedId);
    QVERIFY(source.frames.front().groups.size() == 7);
    QVERIFY(source.frames.front().groups[2].isDeformed());
    const QString target = dir.filePath(QStringLiteral("scene.obj"));
    const auto result = exportAnimation(source, objOptions(target));
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QCOMPARE(result->files, QStringList({target, dir.filePath(QStringLiteral("scene.mtl"))}));
    QCOMPARE(result->fileCount, qint64(2));
    // The dot and the line are left out and said so; the hidden and the empty object are not
    // counted.
    QVERIFY2(result->note.contains(QLatin1String("2 object")), qPrintable(result->note));
    QCOMPARE(filesIn(dir.path()), QStringList({"scene.mtl", "scene.obj"}));

    const ParsedObj obj = parseObj(readAll(target));
    QVERIFY2(obj.problem.isEmpty(), qPrintable(obj.problem));
    QCOMPARE(obj.library, std::string("scene.mtl"));
    QCOMPARE(obj.objects.size(), std::size_t(3));
    QCOMPARE(obj.objects[0].name, std::string("Body"));
    QCOMPARE(obj.objects[1].name, std::string("Left_arm"));
    QCOMPARE(obj.objects[2].name, std::string("Body_2"));
    QCOMPARE(obj.normals, long(obj.v.size()));

    // The counts are those of the solids the model makes for the frame.
    const auto solids = frameSolids(source.frames.front(), source.settings);
    QVERIFY(solids);
    QCOMPARE(solids->candidates, 5);
    QCOMPARE(solids->skipped, 2);
    for (std::size_t i = 0; i < obj.objects.size(); ++i) {
        const ParsedObject &object = obj.objects[i];
        QCOMPARE(object.group, object.name);
        QCOMPARE(object.material, object.name);
        QCOMPARE(long(object.vertices), long(solids->objects[i].solid.V.rows()));
        QCOMPARE(long(object.faces.size()), long(solids->objects[i].solid.F.rows()));
        QVERIFY(faceIndicesInside(object));
        QVERIFY2(closedAndOriented(object.faces), object.name.c_str());
        QVERIFY2(volumeOf(obj, object) > 0.0, object.name.c_str());
    }

    // y up: canvas y becomes −y. The posed circle lies where it shows, kShift from its rest.
    const auto bounds = [&obj](const ParsedObject &object) {
        QRectF box;
        for (int i = object.firstVertex; i < object.firstVertex + object.vertices; ++i) {
            const auto &p = obj.v[std::size_t(i)];
            box |= QRectF(p[0], p[1], 1e-9, 1e-9);
        }
        return box;
    };
    const QRectF body = bounds(obj.objects[0]), posed = bounds(obj.objects[2]);
    // (The shape includes the pen's band around the outline: a few px.)
    QVERIFY2(std::abs(body.left() - 100) < 5 && std::abs(body.right() - 300) < 5 &&
                 std::abs(body.top() + 300) < 5 && std::abs(body.bottom() + 100) < 5,
             qPrintable(QStringLiteral("%1 %2 %3 %4")
                            .arg(body.left())
                            .arg(body.right())
                            .arg(body.top())
                            .arg(body.bottom())));
    QVERIFY(std::abs(posed.center().x() - (200 + kShift.x())) < 5);
    QVERIFY(std::abs(posed.center().y() + (500 + kShift.y())) < 5);

    const auto materials = parseMtl(readAll(dir.filePath(QStringLiteral("scene.mtl"))));
    QCOMPARE(materials.size(), std::size_t(3));
    QVERIFY(nearColour(materials.at("Body"), kBlue)); // the larger fill, not the first
    QVERIFY(nearColour(materials.at("Left_arm"), kGreen));
    QVERIFY(nearColour(materials.at("Body_2"), 0xff000000));
    QCOMPARE(materials.at("Body")[3], 1.0);
}

void TestExportObj::exampleFrameIsClosedSolids()
{
    const ExportSource source = loadExample();
    QVERIFY(!source.frames.empty());
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("walk.obj"));
    const auto result = exportAnimation(source, objOptions(target));
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    const ParsedObj obj = parseObj(readAll(target));
    QVERIFY2(obj.problem.isEmpty(), qPrintable(obj.problem));
    const auto materials = parseMtl(readAll(objMaterialPath(target)));
    const Frame &frame = source.frames[std::size_t(std::max(0, source.settings.playStart))];
    const auto solids = frameSolids(frame, source.settings);
    QVERIFY(solids && !solids->objects.empty());
    QCOMPARE(obj.objects.size(), solids->objects.size());
    QCOMPARE(materials.size(), obj.objects.size());
    long vertices = 0;
    for (std::size_t i = 0; i < obj.objects.size(); ++i) {
        const ParsedObject &object = obj.objects[i];
        vertices += object.vertices;
        QVERIFY(faceIndicesInside(object));
        QVERIFY2(closedAndOriented(object.faces), object.name.c_str());
        QVERIFY2(volumeOf(obj, object) > 0.0, object.name.c_str());
        QVERIFY(materials.count(object.material));
        const Id id = solids->objects[i].groupId;
        const auto group = std::find_if(frame.groups.begin(), frame.groups.end(),
                                        [id](const StrokeGroup &g) { return g.id == id; });
        QVERIFY(nearColour(materials.at(object.material),
                           objectExportColor(*group, source.settings.closeGap)));
    }
    QCOMPARE(vertices, long(obj.v.size()));
    qInfo("walk.finbook frame 1: %zu objects, %zu vertices, %ld skipped", obj.objects.size(),
          obj.v.size(), long(solids->skipped));
}

void TestExportObj::frameOptionPicksTheDrawing()
{
    ExportSource source = generatedSource();
    Frame second = source.frames.front();
    second.groups.erase(second.groups.begin() + 1, second.groups.end()); // only "Body"
    source.frames.push_back(second);
    QTemporaryDir dir;
    ExportOptions options = objOptions(dir.filePath(QStringLiteral("two.obj")));
    options.firstFrame = options.lastFrame = 1;
    const auto result = exportAnimation(source, options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QVERIFY(result->note.isEmpty());
    QCOMPARE(parseObj(readAll(options.target)).objects.size(), std::size_t(1));

    // A range of several frames is no 3D model.
    options.firstFrame = 0;
    options.overwrite = true;
    const auto range = exportAnimation(source, options);
    QVERIFY(!range);
    QCOMPARE(range.error().code, ExportErrorCode::BadOptions);
    QVERIFY2(range.error().message.contains(QLatin1String("one frame")),
             qPrintable(range.error().message));
}

void TestExportObj::nothingMeshableWritesNothing()
{
    ExportSource source = generatedSource();
    Frame &frame = source.frames.front();
    // Keep the hidden circle, the dot, the line and the empty object only.
    frame.groups.erase(frame.groups.begin(), frame.groups.begin() + 3);
    QCOMPARE(frame.groups.size(), std::size_t(4));
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("out"));
    const auto result = exportAnimation(source, objOptions(folder + QStringLiteral("/dot.obj")));
    QVERIFY(!result);
    QCOMPARE(result.error().code, ExportErrorCode::BadOptions);
    QVERIFY2(result.error().message.contains(QLatin1String("can be made 3D")),
             qPrintable(result.error().message));
    QVERIFY(!QFileInfo::exists(folder)); // not even the folder it would have made

    frame.groups.erase(frame.groups.begin() + 1, frame.groups.begin() + 3); // hidden, empty
    const auto empty = exportAnimation(source, objOptions(dir.filePath(QStringLiteral("e.obj"))));
    QVERIFY(!empty);
    QVERIFY2(empty.error().message.contains(QLatin1String("no drawing")),
             qPrintable(empty.error().message));
    QCOMPARE(filesIn(dir.path()), QStringList());
}

void TestExportObj::armOverTheBodyExportsAsTwoSolids()
{
    // One object: a body (circle r 100) and an arm drawn over it (circle r 60, 110 px right).
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = addObject(doc, QStringLiteral("Figure"));
    doc.undoStack()->push(
        new AddStrokeCommand(&doc, g, circleStroke(QPointF(300, 300), 100, 0xff000000)));
    doc.undoStack()->push(
        new AddStrokeCommand(&doc, g, circleStroke(QPointF(410, 300), 60, 0xff000000)));
    const ExportSource source = exportSource(doc);
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("figure.obj"));
    const auto result = exportAnimation(source, objOptions(target));
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    const ParsedObj obj = parseObj(readAll(target));
    QVERIFY2(obj.problem.isEmpty(), qPrintable(obj.problem));
    QCOMPARE(obj.objects.size(), std::size_t(1));
    const ParsedObject &figure = obj.objects.front();
    QVERIFY(closedAndOriented(figure.faces));
    // Its triangles form two separate closed shells, one over each circle.
    std::vector<int> parent(obj.v.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int v) {
        while (parent[std::size_t(v)] != v)
            v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
        return v;
    };
    for (const auto &f : figure.faces)
        for (int k = 1; k < 3; ++k)
            parent[std::size_t(root(f[std::size_t(k)]))] = root(f[0]);
    std::map<int, std::pair<double, double>> shells; // root → x range
    for (const auto &f : figure.faces)
        for (int v : f) {
            auto [it, added] =
                shells.try_emplace(root(v), obj.v[std::size_t(v)][0], obj.v[std::size_t(v)][0]);
            it->second.first = std::min(it->second.first, obj.v[std::size_t(v)][0]);
            it->second.second = std::max(it->second.second, obj.v[std::size_t(v)][0]);
        }
    QCOMPARE(shells.size(), std::size_t(2));
    std::vector<std::pair<double, double>> ranges;
    for (const auto &[r, range] : shells)
        ranges.push_back(range);
    std::sort(ranges.begin(), ranges.end());
    qInfo("shells span x %.0f…%.0f and %.0f…%.0f", ranges[0].first, ranges[0].second,
          ranges[1].first, ranges[1].second);
    QVERIFY(std::abs(ranges[0].first - 200) < 4 && std::abs(ranges[0].second - 400) < 4);
    QVERIFY(std::abs(ranges[1].first - 350) < 4 && std::abs(ranges[1].second - 470) < 4);
}

void TestExportObj::existingFilesAreRefusedWithoutOverwrite()
{
    const ExportSource source = generatedSource();
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("scene.obj"));
    const QString mtl = dir.filePath(QStringLiteral("scene.mtl"));
    for (const QString &inTheWay : {target, mtl}) {
        for (const QString &path : {target, mtl})
            QFile::remove(path);
        QFile old(inTheWay);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old");
        old.close();
        const auto refused = exportAnimation(source, objOptions(target));
        QVERIFY(!refused);
        QCOMPARE(refused.error().code, ExportErrorCode::TargetExists);
        QCOMPARE(readAll(inTheWay), QByteArray("old"));
        QCOMPARE(filesIn(dir.path()), QStringList({QFileInfo(inTheWay).fileName()}));
        QCOMPARE(existingExportTargets(source, objOptions(target)), QStringList({inTheWay}));

        ExportOptions overwrite = objOptions(target);
        overwrite.overwrite = true;
        QVERIFY(exportAnimation(source, overwrite));
        QVERIFY(readAll(target).startsWith("# Finbook"));
        QVERIFY(readAll(mtl).startsWith("# Finbook"));
        QCOMPARE(filesIn(dir.path()), QStringList({"scene.mtl", "scene.obj"}));
    }
}

// The OBJ's rename fails after the new materials are in place (here: its target became a
// folder while the solids were built): the material file it replaced is back, byte for byte,
// and no hidden copy is left beside it.
void TestExportObj::failedObjPutsTheOldMaterialsBack()
{
    const ExportSource source = generatedSource();
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("scene.obj"));
    const QString mtl = dir.filePath(QStringLiteral("scene.mtl"));
    for (const QString &path : {target, mtl}) {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old " + path.toUtf8());
        old.close();
    }
    ExportOptions overwrite = objOptions(target);
    overwrite.overwrite = true;
    bool blocked = false;
    const auto blockTheObj = [&blocked, &target](qint64, qint64) {
        if (!blocked) {
            QFile::remove(target);
            blocked = QDir().mkdir(target);
        }
        return true;
    };
    const auto failed = exportAnimation(source, overwrite, blockTheObj);
    QVERIFY(blocked);
    QVERIFY(!failed);
    QCOMPARE(readAll(mtl), "old " + mtl.toUtf8());
    QVERIFY(QFileInfo(target).isDir());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System),
             QStringList({QStringLiteral("scene.mtl")}));

    // Without an old material file, the one the export added goes again.
    QVERIFY(QFile::remove(mtl));
    QVERIFY(QDir().rmdir(target));
    blocked = false;
    const auto again = exportAnimation(source, overwrite, blockTheObj);
    QVERIFY(blocked);
    QVERIFY(!again);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System), QStringList());
}

void TestExportObj::cancelLeavesNothing()
{
    const ExportSource source = generatedSource();
    QTemporaryDir dir;
    int calls = 0;
    const auto result = exportAnimation(source, objOptions(dir.filePath(QStringLiteral("c.obj"))),
                                        [&calls](qint64, qint64) { return ++calls < 2; });
    QVERIFY(!result);
    QCOMPARE(result.error().code, ExportErrorCode::Cancelled);
    QCOMPARE(filesIn(dir.path()), QStringList());
}

void TestExportObj::materialFileName_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("material");
    QTest::newRow("suffix") << "walk.obj"
                            << "walk.mtl";
    QTest::newRow("folder with a dot") << "a.b/c"
                                       << "a.b/c.mtl";
    QTest::newRow("trailing dot") << "out/walk."
                                  << "out/walk.mtl";
    QTest::newRow("two dots") << "walk.v2.obj"
                              << "walk.v2.mtl";
    QTest::newRow("hidden") << "dir/.obj"
                            << "dir/.mtl";
}

void TestExportObj::materialFileName()
{
    QFETCH(QString, target);
    QFETCH(QString, material);
    QCOMPARE(objMaterialPath(target), material);
}

void TestExportObj::picturesAreTexturedSolids()
{
    // A posed picture object: a closed solid where the picture shows, its material naming the
    // picture written beside the OBJ, a texture coordinate per vertex.
    Id id = kNoId;
    const ExportSource source = pictureSource(&id);
    const StrokeGroup &group = source.frames.front().groups.back();
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("painted.obj"));
    const auto result = exportAnimation(source, objOptions(target));
    QVERIFY2(result.hasValue(), qPrintable(result ? QString() : result.error().message));
    const QString png = dir.filePath(QStringLiteral("painted_Painted.png"));
    QCOMPARE(result->files,
             (QStringList{target, dir.filePath(QStringLiteral("painted.mtl")), png}));
    const ParsedObj obj = parseObj(readAll(target));
    QVERIFY2(obj.problem.isEmpty(), qPrintable(obj.problem));
    QCOMPARE(obj.objects.size(), std::size_t(1));
    QVERIFY(volumeOf(obj, obj.objects.front()) > 0.0);
    QCOMPARE(obj.vt.size(), obj.v.size());
    QCOMPARE(obj.texturedCorners, long(obj.objects.front().faces.size() * 3));
    const QByteArray mtl = readAll(dir.filePath(QStringLiteral("painted.mtl")));
    QVERIFY(mtl.contains("map_Kd painted_Painted.png\n"));
    QVERIFY(mtl.contains("map_d painted_Painted.png\n"));
    QCOMPARE(QImage(png).convertToFormat(QImage::Format_ARGB32_Premultiplied),
             group.picture->data->image.convertToFormat(QImage::Format_ARGB32_Premultiplied));
    // The texture mesh's own vertices first, where the pose shows them (y up), each mapped to
    // its place in the picture (OBJ's v up).
    const Eigen::MatrixX2d &uv = group.picture->mesh->uv;
    const std::vector<QPointF> &posed = group.deformed->pictureVertices;
    const QSize size = group.picture->data->image.size();
    double worstPlace = 0.0, worstTexel = 0.0;
    for (std::size_t i = 0; i < posed.size(); ++i) {
        worstPlace = std::max({worstPlace, std::abs(obj.v[i][0] - posed[i].x()),
                               std::abs(-obj.v[i][1] - posed[i].y())});
        worstTexel =
            std::max({worstTexel, std::abs(obj.vt[i][0] * size.width() - uv(Eigen::Index(i), 0)),
                      std::abs((1.0 - obj.vt[i][1]) * size.height() - uv(Eigen::Index(i), 1))});
    }
    QVERIFY2(worstPlace < 1e-6, qPrintable(QString::number(worstPlace)));
    QVERIFY2(worstTexel < 1e-6, qPrintable(QString::number(worstTexel)));
    // A picture file in the way is refused as the OBJ would be, and nothing is written.
    QVERIFY(QFile::remove(target));
    QVERIFY(QFile::remove(dir.filePath(QStringLiteral("painted.mtl"))));
    const auto again = exportAnimation(source, objOptions(target));
    QVERIFY(!again.hasValue());
    QVERIFY(again.error().message.contains(QStringLiteral("painted_Painted.png")));
    QVERIFY(!QFileInfo::exists(target));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("painted.mtl"))));
}

QTEST_GUILESS_MAIN(TestExportObj)
#include "tst_export_obj.moc"
