// The Palette panel: a click picks the pen's colour; add, recolour, rename, reorder (buttons and
// drag) and delete are each one undo step; GIMP palettes in and out; user palettes saved and
// loaded; the Brush toolbar's swatches follow the document's palette.
#include "tst_window_support.h"

#include <finbook/model/palette/palette.h>
#include <finbook/ui/palette/palette_panel.h>
#include <finbook/ui/tools/brush_tool_bar.h>
#include <finbook/ui/tools/tool_pen.h>

#include <QListWidget>
#include <QToolButton>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestPalettePanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup() { m_window.reset(); }

    void clickingASwatchPicksThePensColour();
    void theChosenSwatchFollowsThePensColour();
    void editsAreUndoableSteps();
    void dragReordersTheSwatches();
    void gimpPalettesInAndOut();
    void userPalettesAreKeptForEveryDrawing();
    void toolbarSwatchesFollowThePalette();
    void aBadFileChangesNothing();

private:
    ui::PalettePanel *panel() const { return m_window->findChild<ui::PalettePanel *>(); }
    model::Document *doc() const { return m_window->document(); }
    ui::PenTool *pen() const
    {
        return static_cast<ui::PenTool *>(m_window->canvas()->tool(QStringLiteral("tool.pen")));
    }
    QToolButton *button(const char *name) const
    {
        return panel()->findChild<QToolButton *>(QString::fromLatin1(name));
    }
    void clickSwatch(int row)
    {
        QListWidget *grid = panel()->grid();
        const QRect r = grid->visualItemRect(grid->item(row));
        QTest::mouseClick(grid->viewport(), Qt::LeftButton, {}, r.center());
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestPalettePanel::initTestCase()
{
    m_settings = std::make_unique<IsolatedSettings>();
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    qputenv("FINBOOK_PALETTE_DIR", m_dir->filePath(QStringLiteral("palettes")).toUtf8());
}

void TestPalettePanel::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    resetDocument(*doc(), 2);
    QVERIFY(showActive(*m_window));
    QVERIFY(panel());
    QVERIFY(panel()->isVisible()); // in front of the undo history
}

void TestPalettePanel::clickingASwatchPicksThePensColour()
{
    const model::Palette &p = doc()->palette();
    QCOMPARE(p, model::defaultPalette());
    QCOMPARE(panel()->grid()->count(), int(p.swatches.size()));
    clickSwatch(5);
    QCOMPARE(pen()->settings().color.rgb(), p.swatches[5].color);
    QCOMPARE(panel()->nameField()->text(), p.swatches[5].name);
    QCOMPARE(doc()->undoStack()->count(), 0); // picking is not an edit
    // The keys still reach the canvas after the click.
    typeKey(Qt::Key_E);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.eraser"));
}

// A colour picked elsewhere (the eyedropper sets the pen's colour) chooses its swatch; a colour
// no swatch has leaves the choice alone, so Set still recolours that swatch with it.
void TestPalettePanel::theChosenSwatchFollowsThePensColour()
{
    const model::Palette &p = doc()->palette();
    clickSwatch(2);
    QCOMPARE(panel()->currentSwatch(), 2);
    ui::PenSettings s = pen()->settings();
    s.color = QColor::fromRgb(p.swatches[6].color);
    pen()->setSettings(s);
    QCOMPARE(panel()->currentSwatch(), 6);
    QCOMPARE(panel()->nameField()->text(), p.swatches[6].name);
    s.color = QColor(1, 2, 3);
    QVERIFY(std::none_of(p.swatches.begin(), p.swatches.end(),
                         [&](const model::Swatch &w) { return w.color == s.color.rgb(); }));
    pen()->setSettings(s);
    QCOMPARE(panel()->currentSwatch(), 6);
    button("paletteRecolour")->click();
    QCOMPARE(doc()->palette().swatches[6].color, s.color.rgb());
    QCOMPARE(doc()->undoStack()->count(), 1); // choosing is not an edit; Set is
}

void TestPalettePanel::editsAreUndoableSteps()
{
    const model::Palette start = doc()->palette();
    const int n = int(start.swatches.size());
    // Add the pen's colour.
    ui::PenSettings s = pen()->settings();
    s.color = QColor(12, 34, 56);
    pen()->setSettings(s);
    QTest::mouseClick(button("paletteAdd"), Qt::LeftButton);
    QCOMPARE(int(doc()->palette().swatches.size()), n + 1);
    QCOMPARE(doc()->palette().swatches.back().color, qRgb(12, 34, 56));
    QCOMPARE(panel()->currentSwatch(), n);
    // Rename it in the field.
    clickIntoText(panel()->nameField());
    typeText(QStringLiteral("Night sky"));
    typeKey(Qt::Key_Return);
    QCOMPARE(doc()->palette().swatches.back().name, QStringLiteral("Night sky"));
    // Move it two places earlier, then recolour and delete the first swatch.
    QTest::mouseClick(button("paletteEarlier"), Qt::LeftButton);
    QTest::mouseClick(button("paletteEarlier"), Qt::LeftButton);
    QCOMPARE(doc()->palette().swatches[std::size_t(n - 2)].name, QStringLiteral("Night sky"));
    QCOMPARE(panel()->currentSwatch(), n - 2);
    clickSwatch(0);
    s.color = QColor(200, 100, 0);
    pen()->setSettings(s);
    QTest::mouseClick(button("paletteRecolour"), Qt::LeftButton);
    QCOMPARE(doc()->palette().swatches[0].color, qRgb(200, 100, 0));
    QTest::mouseClick(button("paletteRemove"), Qt::LeftButton);
    QCOMPARE(int(doc()->palette().swatches.size()), n);
    QCOMPARE(doc()->palette().swatches[0], start.swatches[1]);
    // Six steps; undoing them all gives the palette back exactly, redo the end state.
    const model::Palette end = doc()->palette();
    QCOMPARE(doc()->undoStack()->count(), 6);
    QCOMPARE(doc()->undoStack()->text(0), QStringLiteral("Add Swatch"));
    for (int i = 0; i < 6; ++i)
        doc()->undoStack()->undo();
    QCOMPARE(doc()->palette(), start);
    QCOMPARE(panel()->grid()->count(), n);
    for (int i = 0; i < 6; ++i)
        doc()->undoStack()->redo();
    QCOMPARE(doc()->palette(), end);
}

void TestPalettePanel::dragReordersTheSwatches()
{
    const model::Palette start = doc()->palette();
    QListWidget *grid = panel()->grid();
    grid->setCurrentRow(0);
    // What a drop does to the list: the row moves (QListWidget's internal move).
    QVERIFY(grid->model()->moveRow(QModelIndex(), 0, QModelIndex(), 4));
    QTRY_COMPARE(doc()->undoStack()->count(), 1);
    const model::Palette &p = doc()->palette();
    QCOMPARE(p.swatches[3], start.swatches[0]);
    QCOMPARE(p.swatches[0], start.swatches[1]);
    QCOMPARE(grid->count(), int(start.swatches.size()));
    doc()->undoStack()->undo();
    QCOMPARE(doc()->palette(), start);
}

void TestPalettePanel::gimpPalettesInAndOut()
{
    const QString path = m_dir->filePath(QStringLiteral("bears.gpl"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("GIMP Palette\nName: Bears\n#\n 90  60  30\tFur\n250 240 230\tMuzzle\n");
    }
    QCOMPARE(panel()->importGpl(path), QString());
    QCOMPARE(doc()->palette().name, QStringLiteral("Bears"));
    QCOMPARE(int(doc()->palette().swatches.size()), 2);
    QCOMPARE(panel()->grid()->count(), 2);
    QCOMPARE(doc()->undoStack()->text(doc()->undoStack()->count() - 1),
             QStringLiteral("Import Palette"));
    const QString out = m_dir->filePath(QStringLiteral("out.gpl"));
    QCOMPARE(panel()->exportGpl(out), QString());
    QFile f(out);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const Expected<model::Palette, QString> back = model::readGpl(f.readAll());
    QVERIFY(back);
    QCOMPARE(*back, doc()->palette());
    doc()->undoStack()->undo();
    QCOMPARE(doc()->palette(), model::defaultPalette());
}

void TestPalettePanel::userPalettesAreKeptForEveryDrawing()
{
    model::Palette mine = doc()->palette();
    mine.swatches.resize(3);
    mine.swatches[2] = {qRgb(1, 2, 3), QStringLiteral("Ink")};
    doc()->setPalette(mine);
    QCOMPARE(panel()->saveAsUserPalette(QStringLiteral(" Comic / inks ")), QString());
    QVERIFY(ui::PalettePanel::userPalettes().contains(QStringLiteral("Comic - inks")));
    QVERIFY(!panel()->saveAsUserPalette(QStringLiteral("  ")).isEmpty());
    // Another drawing loads it.
    m_window.reset();
    init();
    QCOMPARE(doc()->palette(), model::defaultPalette());
    QCOMPARE(panel()->loadUserPalette(QStringLiteral("Comic - inks")), QString());
    QCOMPARE(doc()->palette().swatches, mine.swatches);
    QCOMPARE(doc()->palette().name, QStringLiteral("Comic - inks"));
    QCOMPARE(doc()->undoStack()->count(), 1);
}

void TestPalettePanel::toolbarSwatchesFollowThePalette()
{
    auto *brush = m_window->findChild<ui::BrushToolBar *>();
    QVERIFY(brush);
    QVERIFY(brush->findChild<QToolButton *>(QStringLiteral("swatch#d03030")));
    model::Palette p;
    p.name = QStringLiteral("Two");
    p.swatches = {{qRgb(0x11, 0x22, 0x33), QStringLiteral("Navy")},
                  {qRgb(0xfe, 0xdc, 0xba), QString()}};
    doc()->undoStack()->push(new model::SetPaletteCommand(doc(), p, QStringLiteral("Import")));
    QTRY_VERIFY(!brush->findChild<QToolButton *>(QStringLiteral("swatch#d03030")));
    QToolButton *navy = brush->findChild<QToolButton *>(QStringLiteral("swatch#112233"));
    QVERIFY(navy);
    QVERIFY(navy->toolTip().contains(QStringLiteral("Navy")));
    QTest::mouseClick(navy, Qt::LeftButton);
    QCOMPARE(pen()->settings().color.rgb(), qRgb(0x11, 0x22, 0x33));
    doc()->undoStack()->undo();
    QTRY_VERIFY(brush->findChild<QToolButton *>(QStringLiteral("swatch#d03030")));
}

void TestPalettePanel::aBadFileChangesNothing()
{
    const QString path = m_dir->filePath(QStringLiteral("picture.gpl"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("\x89PNG\r\n\x1a\n");
    }
    const QString said = panel()->importGpl(path);
    QVERIFY2(said.contains(QStringLiteral("picture.gpl")) && said.contains(QStringLiteral("GIMP")),
             qPrintable(said));
    QVERIFY(!panel()->importGpl(m_dir->filePath(QStringLiteral("missing.gpl"))).isEmpty());
    QCOMPARE(doc()->undoStack()->count(), 0);
    QCOMPARE(doc()->palette(), model::defaultPalette());
    // A folder where the file should go: said, nothing written.
    QVERIFY(QDir().mkpath(m_dir->filePath(QStringLiteral("taken.gpl"))));
    QVERIFY(!panel()->exportGpl(m_dir->filePath(QStringLiteral("taken.gpl"))).isEmpty());
}

QTEST_MAIN(TestPalettePanel)
#include "tst_palette_panel.moc"
