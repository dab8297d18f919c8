// Picture objects (issue 51): a picture drawn through its mesh is its own pixels at rest, is
// carried by pins without cracks, comes back to its pixels when the pins go back, bakes into a
// new rest picture with Apply Pose (undone exactly), saves once per document however many
// frames show it and opens again byte for byte, and a damaged picture section is refused (or,
// recovering, left out) with a sentence.
#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/inbetween_plan.h>
#include <finbook/model/object_commands.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/cut_out_layers.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>

#include <QPainter>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace finbook;
using namespace finbook::model;

class TestPictureObject : public QObject {
    Q_OBJECT
private slots:
    void restDrawsThePictureUnchanged();
    void pinsCarryThePictureWithoutCracks();
    void pinsBackAtRestGiveTheOriginal();
    void applyPoseBakesThePictureAndUndoes();
    void importIsOneUndoStep();
    void saveOpenKeepsOnePictureForAllFrames();
    void damagedPicturesAreRefusedOrLeftOut();
    void exportsShowThePictureAsPosed_data();
    void exportsShowThePictureAsPosed();
    void cutOutTurnsPiecesRigidlyWithSockets();
    void mergeStacksPicturesAndRefusesCoveringThem();
};

namespace {

constexpr int kW = 160, kH = 120;
const QPointF kAt(40, 30);

// A painted cut-out: a soft-edged ellipse with a gradient and stripes, transparent around.
QImage paintedPicture()
{
    QImage image(kW, kH, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QLinearGradient gradient(0, 0, kW, kH);
    gradient.setColorAt(0, QColor(220, 40, 30));
    gradient.setColorAt(1, QColor(30, 90, 220));
    p.setBrush(gradient);
    p.setPen(Qt::NoPen);
    p.drawEllipse(QRectF(6, 8, kW - 12, kH - 16));
    p.setPen(QPen(QColor(250, 240, 60), 3));
    for (int x = 20; x < kW; x += 17)
        p.drawLine(QPointF(x, 20), QPointF(x - 10, kH - 20));
    return image;
}

StrokeGroup pictureGroup()
{
    auto g = makePictureObject(PictureLayer{QStringLiteral("blob"), paintedPicture(), {}}, kAt);
    if (!g)
        qFatal("%s", qPrintable(g.error()));
    return *g;
}

QImage render(const Frame &frame, QSize size = QSize(240, 180))
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    DocumentSettings settings;
    settings.canvasSize = size;
    RenderOptions options;
    options.paintBackground = false;
    paintFrame(p, frame, settings, options);
    return image;
}

// The picture laid on the canvas as it is, by QPainter.
QImage reference(QSize size = QSize(240, 180))
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.drawImage(kAt, paintedPicture());
    return image;
}

int largestDifference(const QImage &a, const QImage &b, int margin = 0,
                      const QImage *mask = nullptr)
{
    int worst = 0;
    for (int y = margin; y < a.height() - margin; ++y)
        for (int x = margin; x < a.width() - margin; ++x) {
            if (mask && qAlpha(mask->pixel(x, y)) != 255)
                continue;
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q)), std::abs(qAlpha(p) - qAlpha(q))});
        }
    return worst;
}

// Pixels well inside the picture: every neighbour within 2 px is opaque.
QImage interior(const QImage &image)
{
    QImage out(image.size(), QImage::Format_ARGB32_Premultiplied);
    out.fill(Qt::transparent);
    for (int y = 2; y < image.height() - 2; ++y)
        for (int x = 2; x < image.width() - 2; ++x) {
            bool inside = true;
            for (int dy = -2; dy <= 2 && inside; ++dy)
                for (int dx = -2; dx <= 2 && inside; ++dx)
                    inside = qAlpha(image.pixel(x + dx, y + dy)) == 255;
            if (inside)
                out.setPixel(x, y, 0xffffffff);
        }
    return out;
}

struct Posed {
    Document doc;
    Id frame = kNoId;
    Id object = kNoId;
};

// A document whose one object is the picture, pinned at its left end and its right end
// lifted by `lift` px.
void pose(Posed &s, double lift)
{
    s.doc.undoStack()->push(new InsertFrameCommand(&s.doc, 0));
    s.frame = s.doc.frameAt(0).id;
    std::vector<StrokeGroup> objects;
    objects.push_back(pictureGroup());
    auto *import = new ImportPictureCommand(&s.doc, s.frame, -1, std::move(objects));
    s.doc.undoStack()->push(import);
    s.object = import->objectIds().front();
    Rig rig;
    const QPointF left = kAt + QPointF(20, kH / 2.0), right = kAt + QPointF(kW - 20, kH / 2.0);
    rig.pins = {{s.doc.allocateId(), left, left},
                {s.doc.allocateId(), right, right + QPointF(0, -lift)}};
    s.doc.setRig(s.object, rig);
    DeformJob job;
    job.groupId = s.object;
    job.key = MeshKey::of(*s.doc.group(s.object), -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    QVERIFY2(setup.hasValue(), qPrintable(setup ? QString() : setup.error()));
    const auto solved = solvePose(**setup, *s.doc.group(s.object));
    QVERIFY(solved.hasValue());
    s.doc.setDeformed(s.object, solved->strokes);
}

} // namespace

void TestPictureObject::restDrawsThePictureUnchanged()
{
    const StrokeGroup g = pictureGroup();
    QVERIFY(g.picture && pictureIsValid(*g.picture));
    QCOMPARE(g.name, QStringLiteral("blob"));
    QVERIFY(g.hasContent() && g.strokes.empty());
    QVERIFY(g.picture->mesh->uv.rows() >= 100); // a real mesh, not two triangles
    Frame frame;
    frame.groups.push_back(g);
    QCOMPARE(largestDifference(render(frame), reference()), 0);
    // Hidden, it is not drawn; a tint keeps its shape in one colour.
    frame.groups[0].visible = false;
    QCOMPARE(qAlpha(render(frame).pixel(int(kAt.x()) + kW / 2, int(kAt.y()) + kH / 2)), 0);
    frame.groups[0].visible = true;
    QImage ghost(240, 180, QImage::Format_ARGB32_Premultiplied);
    ghost.fill(Qt::transparent);
    {
        QPainter p(&ghost);
        DocumentSettings settings;
        settings.canvasSize = ghost.size();
        RenderOptions options;
        options.paintBackground = false;
        options.tint = QColor(0, 0, 255);
        paintFrame(p, frame, settings, options);
    }
    const QRgb centre = ghost.pixel(int(kAt.x()) + kW / 2, int(kAt.y()) + kH / 2);
    QCOMPARE(qRed(centre), 0);
    QVERIFY(qBlue(centre) > 200);
    // A click on the picture finds it; beside it, not.
    QVERIFY(pictureShowsAt(g, kAt + QPointF(kW / 2.0, kH / 2.0)));
    QVERIFY(!pictureShowsAt(g, kAt + QPointF(1, 1))); // the transparent corner
    QVERIFY(!pictureShowsAt(g, kAt + QPointF(kW + 5, 0)));
}

void TestPictureObject::pinsCarryThePictureWithoutCracks()
{
    Posed s;
    pose(s, 30.0);
    const StrokeGroup &g = *s.doc.group(s.object);
    QCOMPARE(g.deformed->pictureVertices.size(), std::size_t(g.picture->mesh->uv.rows()));
    // The lifted end moved up, the pinned end stayed.
    const QRectF shown = shownPictureBounds(g);
    QVERIFY(shown.top() < kAt.y() - 10);
    Frame frame;
    frame.groups.push_back(g);
    const QImage posed = render(frame);
    QVERIFY(largestDifference(posed, reference()) > 50);
    // No cracks: every pixel whose centre lies inside a posed triangle, away from the outline
    // (2 px), shows the picture opaque wherever the rest picture was opaque there.
    const Eigen::MatrixX2d V = shownPictureVertices(g);
    const Eigen::MatrixX3i &F = g.picture->mesh->F;
    const QImage texture = g.picture->data->image;
    int checked = 0, holes = 0;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::Vector2d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
        const Eigen::Vector2d ua = g.picture->mesh->uv.row(F(f, 0)),
                              ub = g.picture->mesh->uv.row(F(f, 1)),
                              uc = g.picture->mesh->uv.row(F(f, 2));
        const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        const int x0 = int(std::floor(std::min({a.x(), b.x(), c.x()})));
        const int x1 = int(std::ceil(std::max({a.x(), b.x(), c.x()})));
        const int y0 = int(std::floor(std::min({a.y(), b.y(), c.y()})));
        const int y1 = int(std::ceil(std::max({a.y(), b.y(), c.y()})));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const Eigen::Vector2d p(x + 0.5, y + 0.5);
                const auto cross = [](Eigen::Vector2d u, Eigen::Vector2d v) {
                    return u.x() * v.y() - u.y() * v.x();
                };
                const double wa = cross(b - p, c - p) / area, wb = cross(c - p, a - p) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0 || wb < 0 || wc < 0)
                    continue;
                const Eigen::Vector2d uv = wa * ua + wb * ub + wc * uc;
                const int tx = int(uv.x()), ty = int(uv.y());
                bool solid = tx >= 2 && ty >= 2 && tx < kW - 2 && ty < kH - 2;
                for (int dy = -2; dy <= 2 && solid; ++dy)
                    for (int dx = -2; dx <= 2 && solid; ++dx)
                        solid = qAlpha(texture.pixel(tx + dx, ty + dy)) == 255;
                if (!solid)
                    continue;
                ++checked;
                holes += qAlpha(posed.pixel(x, y)) != 255;
            }
    }
    QVERIFY(checked > 5000);
    QCOMPARE(holes, 0);
}

void TestPictureObject::pinsBackAtRestGiveTheOriginal()
{
    Posed s;
    pose(s, 0.0); // pinned where they were put: the solve returns the rest pose
    const StrokeGroup &g = *s.doc.group(s.object);
    QVERIFY(g.isDeformed());
    Frame frame;
    frame.groups.push_back(g);
    const QImage shown = render(frame);
    const QImage inside = interior(reference());
    QVERIFY(largestDifference(shown, reference(), 0, &inside) <= 1);
}

void TestPictureObject::applyPoseBakesThePictureAndUndoes()
{
    Posed s;
    pose(s, 30.0);
    const StrokeGroup before = *s.doc.group(s.object);
    Frame posedFrame;
    posedFrame.groups.push_back(before);
    const QImage posed = render(posedFrame);
    const QByteArray saved = serializeFinbook(s.doc);
    s.doc.undoStack()->push(makeApplyPoseCommand(&s.doc, s.object));
    const StrokeGroup &after = *s.doc.group(s.object);
    QVERIFY(after.picture != before.picture);
    QVERIFY(!after.rig.isPosed());
    Frame bakedFrame;
    bakedFrame.groups.push_back(after);
    const QImage baked = render(bakedFrame);
    // What was shown is kept: resampled once, within a few levels inside the picture.
    const QImage inside = interior(posed);
    QVERIFY(largestDifference(baked, posed, 0, &inside) <= 3);
    s.doc.undoStack()->undo();
    QVERIFY(s.doc.group(s.object)->picture == before.picture);
    QCOMPARE(serializeFinbook(s.doc), saved);
    s.doc.undoStack()->redo();
    QVERIFY(s.doc.group(s.object)->picture == after.picture);
}

void TestPictureObject::importIsOneUndoStep()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("blob.png"));
    QVERIFY(paintedPicture().save(path));
    const auto objects = pictureObjectsFromFile(path, QSizeF(640, 480));
    QVERIFY2(objects.hasValue(), qPrintable(objects ? QString() : objects.error()));
    QCOMPARE(objects->size(), std::size_t(1));
    // Centred on the page, on whole pixels.
    QCOMPARE(objects->front().picture->restRect().topLeft(), QPointF(320 - kW / 2, 240 - kH / 2));
    QCOMPARE(objects->front().name, QStringLiteral("blob"));
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id frame = doc.frameAt(0).id;
    const std::size_t groupsBefore = doc.frameAt(0).groups.size();
    auto *import = new ImportPictureCommand(&doc, frame, -1, *objects);
    doc.undoStack()->push(import);
    QCOMPARE(doc.frameAt(0).groups.size(), groupsBefore + 1);
    QVERIFY(doc.frameAt(0).groups.back().picture == objects->front().picture);
    doc.undoStack()->undo();
    QCOMPARE(doc.frameAt(0).groups.size(), groupsBefore);
    doc.undoStack()->redo();
    QCOMPARE(doc.frameAt(0).groups.back().id, import->objectIds().front());
    // A file that is no picture: a sentence naming it.
    const QString text = dir.filePath(QStringLiteral("notes.png"));
    QFile file(text);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("not a picture at all");
    file.close();
    const auto refused = pictureObjectsFromFile(text, QSizeF(640, 480));
    QVERIFY(!refused.hasValue());
    QVERIFY(refused.error().contains(QStringLiteral("notes.png")));
}

void TestPictureObject::saveOpenKeepsOnePictureForAllFrames()
{
    Posed s;
    pose(s, 25.0);
    s.doc.undoStack()->push(new DuplicateFrameCommand(&s.doc, s.frame, 1));
    s.doc.undoStack()->push(new DuplicateFrameCommand(&s.doc, s.frame, 2));
    const QByteArray bytes = serializeFinbook(s.doc);
    // The picture's PNG is in the file once, whatever number of frames show it.
    const QByteArray png = s.doc.group(s.object)->picture->data->png;
    QCOMPARE(bytes.count(png.left(64)), qsizetype(1));
    const auto loaded = readFinbook(bytes);
    QVERIFY2(loaded.hasValue(), qPrintable(loaded ? QString() : loaded.error().message));
    Document reopened;
    adoptLoadedDocument(reopened, *loaded);
    QCOMPARE(reopened.frameCount(), s.doc.frameCount());
    const StrokeGroup &first = reopened.frameAt(0).groups.back();
    QVERIFY(first.picture && pictureIsValid(*first.picture));
    QCOMPARE(first.picture->place, s.doc.group(s.object)->picture->place);
    QCOMPARE(first.picture->restRect().topLeft(), kAt);
    QCOMPARE(first.picture->data->image, s.doc.group(s.object)->picture->data->image);
    QCOMPARE(first.picture->mesh->uv, s.doc.group(s.object)->picture->mesh->uv);
    QCOMPARE(first.picture->mesh->F, s.doc.group(s.object)->picture->mesh->F);
    QCOMPARE(first.deformed->pictureVertices, s.doc.group(s.object)->deformed->pictureVertices);
    for (int i = 1; i < reopened.frameCount(); ++i) {
        const StrokeGroup &later = reopened.frameAt(i).groups.back();
        QVERIFY(later.picture->data == first.picture->data);
        // The same drawing for meshing, precomputes and in-betweens, though each object of the
        // opened file holds its own picture record.
        QVERIFY(later.picture != first.picture);
        QVERIFY(MeshKey::of(later, -1.0) == MeshKey::of(first, -1.0));
    }
    // In-betweens between two frames of it interpolate its pins.
    const InbetweenPlan plan =
        planInbetweens(reopened.frameAt(0), reopened.frameAt(1), std::vector<double>{0.5});
    QCOMPARE(plan.interpolatedCount(), 1);
    Frame a, b;
    a.groups.push_back(*s.doc.group(s.object));
    b.groups.push_back(first);
    QCOMPARE(largestDifference(render(a), render(b)), 0);
    QCOMPARE(serializeFinbook(reopened), bytes);
    // A document without pictures has no picture section.
    Document plain;
    QVERIFY(!serializeFinbook(plain).contains("PICT"));
}

void TestPictureObject::damagedPicturesAreRefusedOrLeftOut()
{
    Posed s;
    pose(s, 0.0);
    const QByteArray bytes = serializeFinbook(s.doc);
    const qsizetype section = bytes.indexOf("PICT");
    QVERIFY(section > 0);
    // The width: 50,000 px claimed.
    QByteArray huge = bytes;
    const quint32 width = 50000;
    qToLittleEndian<quint32>(width, huge.data() + section + 12 + 4);
    QVERIFY(!readFinbook(huge).hasValue()); // the checksum, first
    QStringList problems;
    const auto recovered = recoverFinbook(huge, &problems);
    QVERIFY(recovered.hasValue());
    QVERIFY2(problems.join(QLatin1Char('\n')).contains(QStringLiteral("50000")),
             qPrintable(problems.join(QLatin1Char('\n'))));
    for (const Frame &f : recovered->frames)
        for (const StrokeGroup &g : f.groups)
            QVERIFY(!g.picture);
    // The PNG's bytes damaged: it does not decode, and nothing crashes.
    QByteArray broken = bytes;
    const qsizetype png = broken.indexOf("IDAT", section);
    QVERIFY(png > 0);
    for (qsizetype i = png + 8; i < png + 60 && i < broken.size(); ++i)
        broken[i] = char(broken[i] ^ 0x5a);
    QVERIFY(!readFinbook(broken).hasValue());
    problems.clear();
    QVERIFY(recoverFinbook(broken, &problems).hasValue());
    QVERIFY(!problems.isEmpty());
    // Cut inside the picture section.
    QVERIFY(!readFinbook(bytes.left(section + 200)).hasValue());
}

void TestPictureObject::exportsShowThePictureAsPosed_data()
{
    QTest::addColumn<int>("format");
    QTest::newRow("png") << int(ExportFormat::PngSequence);
    QTest::newRow("svg") << int(ExportFormat::SvgSequence);
}

void TestPictureObject::exportsShowThePictureAsPosed()
{
    QFETCH(int, format);
    Posed s;
    pose(s, 30.0);
    DocumentSettings settings = s.doc.settings();
    settings.canvasSize = QSize(240, 180);
    QTemporaryDir dir;
    ExportOptions o;
    o.format = ExportFormat(format);
    o.target = dir.filePath(QStringLiteral("frames"));
    const auto result = exportAnimation(ExportSource{s.doc.frames(), settings}, o);
    QVERIFY(result.hasValue());
    QCOMPARE(result->files.size(), 1);
    QImage exported;
    if (o.format == ExportFormat::SvgSequence) {
        QSvgRenderer renderer(result->files.front());
        QVERIFY(renderer.isValid());
        exported = QImage(240, 180, QImage::Format_ARGB32_Premultiplied);
        exported.fill(Qt::white);
        QPainter painter(&exported);
        renderer.render(&painter);
    } else {
        exported =
            QImage(result->files.front()).convertToFormat(QImage::Format_ARGB32_Premultiplied);
    }
    // The posed picture as the canvas paints it, on the page's white.
    QImage shown(240, 180, QImage::Format_ARGB32_Premultiplied);
    shown.fill(Qt::white);
    {
        QPainter p(&shown);
        RenderOptions options;
        options.paintBackground = false;
        paintFrame(p, s.doc.frameAt(0), settings, options);
    }
    const QImage inside = interior(render(s.doc.frameAt(0)));
    int opaque = 0;
    for (int y = 0; y < inside.height(); ++y)
        for (int x = 0; x < inside.width(); ++x)
            opaque += qAlpha(inside.pixel(x, y)) == 255;
    QVERIFY(opaque > 5000);
    QVERIFY(largestDifference(exported, shown, 0, &inside) <= 3);
}

namespace {

// A painted figure, opaque inside its outline: a body with an arm reaching out to the right,
// striped across so that a piece drawn turned or stretched shows.
QImage paintedFigure()
{
    QImage image(260, 180, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QPainterPath figure;
    figure.addRoundedRect(QRectF(10, 10, 120, 160), 40, 40);
    figure.addRoundedRect(QRectF(100, 66, 150, 28), 14, 14);
    figure.setFillRule(Qt::WindingFill);
    p.setClipPath(figure.simplified());
    for (int x = 0; x < 260; x += 12) {
        p.fillRect(QRectF(x, 0, 6, 180), QColor(200, 60, 40));
        p.fillRect(QRectF(x + 6, 0, 6, 180), QColor(40, 90, 200));
    }
    return image;
}

// How much the posed triangle abc is longer along an edge than it is at rest (1 unchanged).
double stretch(const Eigen::MatrixX2d &rest, const Eigen::MatrixX2d &posed,
               const Eigen::Vector3i &f)
{
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) {
        const int i = f(k), j = f((k + 1) % 3);
        worst = std::max(worst, (posed.row(i) - posed.row(j)).norm() /
                                    std::max(1e-9, (rest.row(i) - rest.row(j)).norm()));
    }
    return worst;
}

} // namespace

void TestPictureObject::cutOutTurnsPiecesRigidlyWithSockets()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id frame = doc.frameAt(0).id;
    auto made = makePictureObject(PictureLayer{QStringLiteral("figure"), paintedFigure(), {}},
                                  QPointF(20, 20));
    QVERIFY(made.hasValue());
    std::vector<StrokeGroup> objects{*made};
    auto *import = new ImportPictureCommand(&doc, frame, -1, std::move(objects));
    doc.undoStack()->push(import);
    const Id object = import->objectIds().front();
    auto built = buildSkeletonRig(*doc.group(object), {}, std::nullopt, doc.settings().closeGap);
    QVERIFY2(built.hasValue(), qPrintable(built ? QString() : built.error()));
    Rig rig;
    rig.skeleton = *built;
    rig.skeleton.mode = SkinningMode::CutOut;
    rig.skeleton.angles.assign(std::size_t(built->jointCount()), 0.0);
    // The arm: the joint whose bone runs farthest to the right, turned down by 60° at its base
    // (the joint it hangs from, inside the body).
    const std::vector<QPointF> joints = built->posedJoints();
    int tip = 0;
    for (int j = 0; j < built->jointCount(); ++j)
        if (joints[std::size_t(j)].x() > joints[std::size_t(tip)].x())
            tip = j;
    int base = tip;
    while (built->parent[std::size_t(base)] >= 0 &&
           joints[std::size_t(built->parent[std::size_t(base)])].x() > 20 + 135)
        base = built->parent[std::size_t(base)];
    QVERIFY(built->parent[std::size_t(base)] >= 0);
    rig.skeleton.angles[std::size_t(base)] = 60.0 * std::numbers::pi / 180.0;
    doc.setRig(object, rig);
    DeformJob job;
    job.groupId = object;
    job.key = MeshKey::of(*doc.group(object), -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    QVERIFY2(setup.hasValue(), qPrintable(setup ? QString() : setup.error()));
    const auto solved = solvePose(**setup, *doc.group(object));
    QVERIFY(solved.hasValue());
    doc.setDeformed(object, solved->strokes);
    const StrokeGroup &g = *doc.group(object);
    const DeformedStrokes &pose = *g.deformed;
    QVERIFY(!pose.sockets.empty());
    QVERIFY(!pose.pictureLayers.isEmpty());
    // Every triangle of the picture is drawn once, in pieces; each socket as a fan.
    const ShownPictureMesh shown = shownPictureMesh(g);
    const Eigen::Index faces = g.picture->mesh->F.rows();
    int sockets = 0;
    for (const QPainterPath &socket : pose.sockets)
        sockets += socket.isEmpty() ? 0 : 1;
    QVERIFY(sockets >= 1);
    QCOMPARE(shown.F.rows(), faces + sockets * 32);
    // The pieces turn rigidly: no triangle of the picture stretches across a cut. (Drawn
    // through the uncut mesh, those at the shoulder stretch far over the turn.)
    const Eigen::MatrixX2d restShown = [&] {
        Eigen::MatrixX2d rest(shown.uv.rows(), 2);
        for (Eigen::Index i = 0; i < rest.rows(); ++i) {
            const QPointF p = g.picture->place.map(QPointF(shown.uv(i, 0), shown.uv(i, 1)));
            rest.row(i) << p.x(), p.y();
        }
        return rest;
    }();
    double worstCut = 0.0, worstUncut = 0.0;
    for (Eigen::Index f = shown.F.rows() - faces; f < shown.F.rows(); ++f)
        worstCut = std::max(worstCut, stretch(restShown, shown.V, shown.F.row(f).transpose()));
    const Eigen::MatrixX2d uncut = shownPictureVertices(g), rest = g.picture->restVertices();
    for (Eigen::Index f = 0; f < faces; ++f)
        worstUncut =
            std::max(worstUncut, stretch(rest, uncut, g.picture->mesh->F.row(f).transpose()));
    QVERIFY2(worstCut < 1.02, qPrintable(QString::number(worstCut)));
    QVERIFY2(worstUncut > 1.3, qPrintable(QString::number(worstUncut)));
    // The sockets fill the joint from the picture's own pixels: the whole posed disk (less a
    // pixel at its rim) is opaque, on the outer side of the bend too, where neither piece lies.
    Frame shownFrame;
    shownFrame.groups.push_back(g);
    const QImage posed = render(shownFrame, QSize(360, 300));
    int inDisk = 0, holes = 0;
    for (const QPainterPath &socket : pose.sockets) {
        if (socket.isEmpty())
            continue;
        const QRectF box = socket.boundingRect();
        const QPointF centre = box.center();
        const double radius = box.width() / 2.0 - 1.5;
        for (int y = int(box.top()); y <= int(box.bottom()); ++y)
            for (int x = int(box.left()); x <= int(box.right()); ++x) {
                if (std::hypot(x + 0.5 - centre.x(), y + 0.5 - centre.y()) > radius)
                    continue;
                ++inDisk;
                holes += qAlpha(posed.pixel(x, y)) != 255;
            }
    }
    QVERIFY(inDisk > 100);
    QCOMPARE(holes, 0);
    // Apply Pose keeps what was shown, resampled once; undo gives the picture back.
    const auto before = g.picture;
    doc.undoStack()->push(makeApplyPoseCommand(&doc, object));
    Frame bakedFrame;
    bakedFrame.groups.push_back(*doc.group(object));
    const QImage inside = interior(posed);
    QVERIFY(largestDifference(render(bakedFrame, QSize(360, 300)), posed, 0, &inside) <= 3);
    doc.undoStack()->undo();
    QVERIFY(doc.group(object)->picture == before);
    // A file keeps the pose but not the layers; reading it brings them back, drawn the same.
    auto loaded = readFinbook(serializeFinbook(doc));
    QVERIFY2(loaded.hasValue(), qPrintable(loaded ? QString() : loaded.error().message));
    const StrokeGroup &back = loaded->frames.front().groups.back();
    QVERIFY(back.picture && back.isDeformed() && back.deformed->pictureLayers.isEmpty());
    QCOMPARE(restoreCutOutLayers(loaded->frames, doc.settings().closeGap), 1);
    QVERIFY(!back.deformed->pictureLayers.isEmpty());
    Frame backFrame;
    backFrame.groups.push_back(back);
    QCOMPARE(largestDifference(render(backFrame, QSize(360, 300)), posed), 0);
}

void TestPictureObject::mergeStacksPicturesAndRefusesCoveringThem()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id frame = doc.frameAt(0).id;
    // Two soft-edged pictures overlapping, the upper one mirrored and moved by whole pixels,
    // and a drawn object on top of both.
    auto upperPicture = makePictureObject(
        PictureLayer{QStringLiteral("mirrored"), paintedPicture().mirrored(true, false), {}},
        kAt + QPointF(37, 21));
    QVERIFY(upperPicture.hasValue());
    auto *import = new ImportPictureCommand(&doc, frame, -1, {pictureGroup(), *upperPicture});
    doc.undoStack()->push(import);
    const Id lower = import->objectIds()[0], upper = import->objectIds()[1];
    auto *drawn = new AddObjectCommand(&doc, frame, -1, QStringLiteral("lines"));
    doc.undoStack()->push(drawn);
    auto line = std::make_shared<StrokeData>();
    line->color = 0xff000000;
    line->width = 4.0f;
    for (int i = 0; i <= 40; ++i)
        line->points.push_back({30.0f + 5.0f * float(i), 60.0f + float(i), 0.5f});
    doc.undoStack()->push(new AddStrokeCommand(&doc, drawn->groupId(), line));
    const QSize size(300, 220);
    const QImage before = render(doc.frameAt(0), size);
    const QByteArray saved = serializeFinbook(doc);

    // Lines under a picture: refused, with a sentence naming both, and the command changes
    // nothing if pushed anyway.
    const QString refusal = mergeRefusal(doc, {drawn->groupId(), lower});
    QVERIFY(refusal.contains(QStringLiteral("lines")) && refusal.contains(QStringLiteral("blob")));
    QVERIFY(mergeRefusal(doc, {lower, upper, drawn->groupId()}).isEmpty());
    QVERIFY(!mergeRefusal(doc, {lower, drawn->groupId(), upper}).isEmpty());
    const int steps = doc.undoStack()->index();
    doc.undoStack()->push(new ReorderObjectCommand(&doc, drawn->groupId(), 0)); // lines at bottom
    const QImage reordered = render(doc.frameAt(0), size);
    doc.undoStack()->push(new MergeObjectsCommand(&doc, lower, drawn->groupId()));
    QVERIFY(doc.group(lower) && doc.group(lower)->picture);
    QCOMPARE(render(doc.frameAt(0), size), reordered);
    while (doc.undoStack()->index() > steps)
        doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), saved);

    // Two pictures and the lines above them: one object, one picture covering both, and the
    // same look (the pictures lie on whole pixels, so no pixel is resampled).
    const QRectF both =
        shownPictureBounds(*doc.group(lower)).united(shownPictureBounds(*doc.group(upper)));
    doc.undoStack()->push(new MergeObjectsCommand(&doc, upper, lower));
    doc.undoStack()->push(new MergeObjectsCommand(&doc, drawn->groupId(), lower));
    QVERIFY(!doc.group(upper) && !doc.group(drawn->groupId()));
    const StrokeGroup &merged = *doc.group(lower);
    QVERIFY(merged.picture && pictureIsValid(*merged.picture));
    QVERIFY(merged.picture->restRect().contains(both));
    QVERIFY(merged.picture->restRect().width() < both.width() + 2);
    QCOMPARE(merged.strokes.size(), std::size_t(1));
    const QImage after = render(doc.frameAt(0), size);
    QVERIFY2(largestDifference(after, before) <= 1,
             qPrintable(QString::number(largestDifference(after, before))));
    const auto mergedPicture = merged.picture;
    // Undo gives both objects back as they were; redo the very same merged picture.
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), saved);
    doc.undoStack()->redo();
    doc.undoStack()->redo();
    QVERIFY(doc.group(lower)->picture == mergedPicture);
    // A picture merged into an object without one keeps its very pixels.
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    auto *empty = new AddObjectCommand(&doc, frame, 0, QStringLiteral("empty"));
    doc.undoStack()->push(empty);
    const auto lowerPicture = doc.group(lower)->picture;
    doc.undoStack()->push(new MergeObjectsCommand(&doc, lower, empty->groupId()));
    QVERIFY(doc.group(empty->groupId())->picture == lowerPicture);
}

QTEST_MAIN(TestPictureObject)
#include "tst_picture_object.moc"
