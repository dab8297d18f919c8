// File → Import Mesh: a 2D OFF mesh becomes an object whose outline is strokes, one undo
// step, ready for a cage (the harmonic-coordinates notebook's case, done by hand). File →
// Import Picture and dropped files: picture objects.
#include "tst_window_support.h"

#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/ui/cage/cage_actions.h>

#include <QAction>
#include <QClipboard>
#include <QMimeData>
#include <QPainter>
#include <QTemporaryDir>

using namespace finbook;

class TestImportMesh : public QObject {
    Q_OBJECT
private slots:
    void init() { m_settings = std::make_unique<test::IsolatedSettings>(); }
    void cleanup() { m_settings.reset(); }
    void offMeshBecomesAnObject();
    void badMeshIsReportedAndChangesNothing();
    void picturesComeInByMenuAndByDrop();
    void pastedPictureBecomesAnObject();
    void aFlatBackgroundIsKeyedOutWhenAsked();

private:
    std::unique_ptr<test::IsolatedSettings> m_settings;
};

namespace {
class QuietWindow : public ui::MainWindow {
public:
    QStringList errors;
    bool keyOut = false;             // the answer to "make the background transparent?"
    std::vector<QColor> keyOutAsked; // the background colours it was asked about
    void reportError(const QString &, const QString &message) override { errors << message; }
    bool askKeyOutBackground(const QString &, QColor background) override
    {
        keyOutAsked.push_back(background);
        return keyOut;
    }
};
} // namespace

void TestImportMesh::offMeshBecomesAnObject()
{
    QuietWindow window;
    model::Document *doc = window.document();
    const int objects = int(doc->frameAt(0).groups.size());
    QVERIFY(
        window.importMesh(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/woody-synthetic.off")));
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects + 1);
    const model::StrokeGroup &g = doc->frameAt(0).groups.back();
    QCOMPARE(g.name, QStringLiteral("woody-synthetic"));
    QVERIFY(!g.strokes.empty());
    // Closed outlines inside the canvas.
    const QSize canvas = doc->settings().canvasSize;
    for (const model::Stroke &s : g.strokes) {
        QCOMPARE(s.data->points.front(), s.data->points.back());
        for (const model::StrokePoint &p : s.data->points)
            QVERIFY(p.x >= 0 && p.y >= 0 && p.x <= canvas.width() && p.y <= canvas.height());
    }
    // A cage fits around it.
    auto cage = model::fitCage(g, 16);
    QVERIFY2(cage.hasValue(), cage ? "" : qPrintable(cage.error()));
    QVERIFY(!model::cageProblem(g, *cage));
    // One undo step takes it away again.
    doc->undoStack()->undo();
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects);
}

// File → Import Picture and a drop of picture files: picture objects on the current frame,
// one undo step per file; a file that is no picture is reported and changes nothing.
void TestImportMesh::picturesComeInByMenuAndByDrop()
{
    QuietWindow window;
    model::Document *doc = window.document();
    QTemporaryDir dir;
    QImage picture(90, 60, QImage::Format_ARGB32_Premultiplied);
    picture.fill(Qt::transparent);
    {
        QPainter p(&picture);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setBrush(QColor(40, 160, 90));
        p.drawEllipse(QRectF(5, 5, 80, 50));
    }
    const QString png = dir.filePath(QStringLiteral("leaf.png"));
    QVERIFY(picture.save(png));
    const int objects = int(doc->frameAt(0).groups.size());
    QVERIFY(window.importPicture(png));
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects + 1);
    QVERIFY(doc->frameAt(0).groups.back().picture);
    QCOMPARE(doc->frameAt(0).groups.back().name, QStringLiteral("leaf"));
    QCOMPARE(window.editorState()->currentGroupId(), doc->frameAt(0).groups.back().id);
    doc->undoStack()->undo();
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects);

    // Dropped on the window: the same, once per file.
    const auto drop = [&](const QList<QUrl> &urls) {
        QMimeData mime;
        mime.setUrls(urls);
        QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                              Qt::NoModifier);
        QApplication::sendEvent(&window, &enter);
        if (!enter.isAccepted())
            return false;
        QDropEvent dropped(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &dropped);
        return dropped.isAccepted();
    };
    QVERIFY(drop({QUrl::fromLocalFile(png)}));
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects + 1);
    // Text is no file: refused.
    QVERIFY(!drop({QUrl(QStringLiteral("https://example.com/leaf.png"))}));
    // A file that is not a picture: reported, nothing added.
    const QString notes = dir.filePath(QStringLiteral("notes.png"));
    QFile file(notes);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("no picture here");
    file.close();
    window.errors.clear();
    QVERIFY(drop({QUrl::fromLocalFile(notes)}));
    QCOMPARE(window.errors.size(), 1);
    QVERIFY(window.errors.front().contains(QStringLiteral("notes.png")));
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects + 1);
}

// Edit → Paste with a picture on the clipboard (as Krita or a browser put it there).
void TestImportMesh::pastedPictureBecomesAnObject()
{
    QuietWindow window;
    model::Document *doc = window.document();
    QImage picture(64, 48, QImage::Format_ARGB32_Premultiplied);
    picture.fill(QColor(200, 60, 40));
    QApplication::clipboard()->setImage(picture);
    QAction *paste = window.findChild<QAction *>(QStringLiteral("edit.paste"));
    QVERIFY(paste);
    QVERIFY(paste->isEnabled());
    const int objects = int(doc->frameAt(0).groups.size());
    paste->trigger();
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects + 1);
    const model::StrokeGroup &g = doc->frameAt(0).groups.back();
    QVERIFY(g.picture);
    QCOMPARE(g.picture->data->image.size(), picture.size());
    // Centred on the page when the mouse is not over the canvas.
    const QSizeF page(doc->settings().canvasSize);
    QCOMPARE(g.picture->restRect().center(), QRectF(QPointF(0, 0), page).center());
    doc->undoStack()->undo();
    QCOMPARE(int(doc->frameAt(0).groups.size()), objects);
    QApplication::clipboard()->clear();
}

// A drawing exported on white: Import Picture offers to make the white transparent, so the
// object is the drawing (its shape, its skeleton), not the page; declined, it stays opaque.
void TestImportMesh::aFlatBackgroundIsKeyedOutWhenAsked()
{
    QTemporaryDir dir;
    QImage scan(120, 90, QImage::Format_RGB32);
    scan.fill(Qt::white);
    {
        QPainter p(&scan);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setBrush(QColor(200, 40, 40));
        p.setPen(Qt::NoPen);
        p.drawEllipse(QRectF(30, 20, 60, 50));
    }
    const QString path = dir.filePath(QStringLiteral("scan.png"));
    QVERIFY(scan.save(path));
    for (const bool answer : {true, false}) {
        QuietWindow window;
        window.keyOut = answer;
        QVERIFY(window.importPicture(path));
        QCOMPARE(window.keyOutAsked.size(), std::size_t(1));
        QCOMPARE(window.keyOutAsked.front(), QColor(Qt::white));
        const model::StrokeGroup &g = window.document()->frameAt(0).groups.back();
        const QImage &kept = g.picture->data->image;
        QCOMPARE(qAlpha(kept.pixel(2, 2)), answer ? 0 : 255); // the background
        QCOMPARE(qAlpha(kept.pixel(60, 45)), 255);            // the drawing
        QCOMPARE(model::pictureShowsAt(g, g.picture->restRect().topLeft() + QPointF(2, 2)),
                 !answer);
    }
    // A picture with transparency is not asked about.
    QImage cutOut(40, 40, QImage::Format_ARGB32_Premultiplied);
    cutOut.fill(Qt::transparent);
    const QString png = dir.filePath(QStringLiteral("cut.png"));
    {
        QPainter p(&cutOut);
        p.fillRect(QRect(10, 10, 20, 20), Qt::blue);
    }
    QVERIFY(cutOut.save(png));
    QuietWindow window;
    QVERIFY(window.importPicture(png));
    QVERIFY(window.keyOutAsked.empty());
}

void TestImportMesh::badMeshIsReportedAndChangesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.off"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("OFF\n3 1 0\n0 0 0\n1 0 0\n");
    file.close();
    QuietWindow window;
    const int steps = window.document()->undoStack()->count();
    QVERIFY(!window.importMesh(path));
    QCOMPARE(window.errors.size(), 1);
    QCOMPARE(window.document()->undoStack()->count(), steps);
}

QTEST_MAIN(TestImportMesh)
#include "tst_import_mesh.moc"
