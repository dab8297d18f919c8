// File → Import Mesh: a 2D OFF mesh becomes an object whose outline is strokes, one undo
// step, ready for a cage (the harmonic-coordinates notebook's case, done by hand).
#include "tst_window_support.h"

#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/document.h>
#include <finbook/ui/cage/cage_actions.h>

#include <QTemporaryDir>

using namespace finbook;

class TestImportMesh : public QObject {
    Q_OBJECT
private slots:
    void init() { m_settings = std::make_unique<test::IsolatedSettings>(); }
    void cleanup() { m_settings.reset(); }
    void offMeshBecomesAnObject();
    void badMeshIsReportedAndChangesNothing();

private:
    std::unique_ptr<test::IsolatedSettings> m_settings;
};

namespace {
class QuietWindow : public ui::MainWindow {
public:
    QStringList errors;
    void reportError(const QString &, const QString &message) override { errors << message; }
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
