// The document's palette: GIMP palette files in and out, the "palt" section (saved, opened,
// autosaved, left out when default), undo, and bad input refused with a reason.
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/palette/palette.h>
#include <finbook/model/recovery/recovery_store.h>

#include <QtTest>

using namespace finbook;
using namespace finbook::model;

class TestPalette : public QObject {
    Q_OBJECT

private slots:
    void gimpPalettesReadAsGimpWritesThem();
    void gplRoundTrips();
    void badGplIsRefusedWithTheLine_data();
    void badGplIsRefusedWithTheLine();
    void paletteIsSavedOpenedAndAutosaved();
    void aDefaultPaletteWritesNothing();
    void damagedPaletteSectionIsSaid();
    void everyChangeIsOneUndoStep();
    void namesAndColoursAreCleaned();
};

namespace {
Palette sample()
{
    Palette p;
    p.name = QStringLiteral("Skin tones");
    p.swatches = {{qRgb(255, 224, 189), QStringLiteral("Light")},
                  {qRgb(141, 85, 36), QStringLiteral("Deep brown")},
                  {qRgb(0, 0, 0), QString()},
                  {qRgb(12, 200, 7), QStringLiteral("名前 with spaces")}};
    return p;
}
} // namespace

// As GIMP 2.10 writes a palette (and Krita and Inkscape read it).
void TestPalette::gimpPalettesReadAsGimpWritesThem()
{
    const QByteArray gimp = "GIMP Palette\r\n"
                            "Name: Bears\r\n"
                            "Columns: 16\r\n"
                            "#\r\n"
                            "# a comment\r\n"
                            "  8   8   8\tBlack-ish\r\n"
                            "255 255 255\tWhite\r\n"
                            " 68  28   0\tUntitled\r\n"
                            "\r\n";
    const Expected<Palette, QString> p = readGpl(gimp);
    QVERIFY2(p, qPrintable(p ? QString() : p.error()));
    QCOMPARE(p->name, QStringLiteral("Bears"));
    QCOMPARE(int(p->swatches.size()), 3);
    QCOMPARE(p->swatches[0].color, qRgb(8, 8, 8));
    QCOMPARE(p->swatches[0].name, QStringLiteral("Black-ish"));
    QCOMPARE(p->swatches[2].color, qRgb(68, 28, 0));
    // Krita's RGBA variant: the alpha is read and dropped (a palette holds colours).
    const Expected<Palette, QString> rgba =
        readGpl("\xef\xbb\xbfGIMP Palette\nName: K\nChannels: RGBA\n10 20 30 128 Half\n");
    QVERIFY(rgba);
    QCOMPARE(rgba->swatches.front().color, qRgb(10, 20, 30));
    QCOMPARE(rgba->swatches.front().name, QStringLiteral("Half"));
}

void TestPalette::gplRoundTrips()
{
    const Palette p = sample();
    const QByteArray bytes = writeGpl(p);
    QVERIFY(bytes.startsWith("GIMP Palette\nName: Skin tones\n"));
    const Expected<Palette, QString> back = readGpl(bytes);
    QVERIFY(back);
    QCOMPARE(*back, p);
    QCOMPARE(writeGpl(*back), bytes);
}

void TestPalette::badGplIsRefusedWithTheLine_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("said");
    QTest::newRow("not a palette") << QByteArray("\x89PNG\r\n") << QStringLiteral("GIMP Palette");
    QTest::newRow("empty") << QByteArray() << QStringLiteral("GIMP Palette");
    QTest::newRow("a number too big")
        << QByteArray("GIMP Palette\nName: x\n0 0 0 Black\n300 0 0 Red\n")
        << QStringLiteral("line 4");
    QTest::newRow("words for numbers")
        << QByteArray("GIMP Palette\nred green blue\n") << QStringLiteral("line 2");
    QTest::newRow("unknown channels")
        << QByteArray("GIMP Palette\nChannels: CMYK\n") << QStringLiteral("line 2");
    QByteArray many = "GIMP Palette\n";
    for (int i = 0; i <= kMaxSwatches; ++i)
        many += "1 2 3\n";
    QTest::newRow("too many colours") << many << QString::number(kMaxSwatches);
}

void TestPalette::badGplIsRefusedWithTheLine()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, said);
    const Expected<Palette, QString> p = readGpl(bytes);
    QVERIFY(!p);
    QVERIFY2(p.error().contains(said), qPrintable(p.error()));
}

void TestPalette::paletteIsSavedOpenedAndAutosaved()
{
    Document doc;
    doc.undoStack()->push(new SetPaletteCommand(&doc, sample(), QStringLiteral("Import")));
    const QByteArray bytes = serializeFinbook(doc);
    Expected<LoadedDocument, FileError> loaded = readFinbook(bytes);
    QVERIFY(loaded);
    QCOMPARE(loaded->palette, sample());
    Document opened;
    adoptLoadedDocument(opened, std::move(*loaded));
    QCOMPARE(opened.palette(), sample());
    QCOMPARE(serializeFinbook(opened), bytes); // save → open → save is byte-identical
    // The recovery copy carries it too.
    const QByteArray copy =
        recoveryCopyBytes(doc.layers(), doc.settings(), RecoveryInfo{}, {}, {}, {}, doc.palette());
    Expected<LoadedDocument, FileError> recovered = readFinbook(copy);
    QVERIFY(recovered);
    QCOMPARE(recovered->palette, sample());
    // A new document after it starts with the default palette again.
    opened.reset(std::vector<Frame>(1), DocumentSettings{}, 1);
    QCOMPARE(opened.palette(), defaultPalette());
}

void TestPalette::aDefaultPaletteWritesNothing()
{
    Document doc;
    QCOMPARE(doc.palette(), defaultPalette());
    QVERIFY(!readAncillarySection(serializeFinbook(doc), "palt"));
    doc.setPalette(sample());
    QVERIFY(readAncillarySection(serializeFinbook(doc), "palt"));
}

void TestPalette::damagedPaletteSectionIsSaid()
{
    QVERIFY(!readPaletteSection(QByteArray()));
    QByteArray payload = paletteSectionPayload(sample());
    QCOMPARE(*readPaletteSection(payload), sample());
    QVERIFY(!readPaletteSection(payload.chopped(1)));
    QVERIFY(!readPaletteSection(payload + "x"));
    QByteArray huge = payload;
    huge[4 + sample().name.toUtf8().size()] = '\xff'; // the count's low byte
    huge[4 + sample().name.toUtf8().size() + 3] = '\x7f';
    const Expected<Palette, QString> claimed = readPaletteSection(huge);
    QVERIFY(!claimed);
    QVERIFY2(claimed.error().contains(QStringLiteral("claims")), qPrintable(claimed.error()));
}

void TestPalette::everyChangeIsOneUndoStep()
{
    Document doc;
    QSignalSpy changed(&doc, &Document::paletteChanged);
    Palette p = doc.palette();
    p.swatches.push_back({qRgb(1, 2, 3), QStringLiteral("Ink")});
    doc.undoStack()->push(new SetPaletteCommand(&doc, p, QStringLiteral("Add Swatch")));
    Palette renamed = doc.palette();
    renamed.swatches.back().name = QStringLiteral("Night ink");
    std::swap(renamed.swatches.front(), renamed.swatches.back());
    doc.undoStack()->push(new SetPaletteCommand(&doc, renamed, QStringLiteral("Rename")));
    QCOMPARE(doc.palette(), renamed);
    QCOMPARE(doc.undoStack()->count(), 2);
    doc.undoStack()->undo();
    QCOMPARE(doc.palette(), p);
    doc.undoStack()->undo();
    QCOMPARE(doc.palette(), defaultPalette());
    doc.undoStack()->redo();
    doc.undoStack()->redo();
    QCOMPARE(doc.palette(), renamed);
    QCOMPARE(changed.count(), 6);
}

void TestPalette::namesAndColoursAreCleaned()
{
    Palette p;
    p.name = QStringLiteral("  two\nlines\t");
    p.swatches = {{0x00123456, QString(1000, QLatin1Char('a'))}};
    const Palette clean = sanitizedPalette(p);
    QCOMPARE(clean.name, QStringLiteral("two lines"));
    QCOMPARE(clean.swatches.front().color, QRgb(0xff123456));
    QCOMPARE(clean.swatches.front().name.size(), kMaxSwatchNameChars);
    // What a document holds is always clean, however it was set.
    Document doc;
    doc.setPalette(p);
    QCOMPARE(doc.palette(), clean);
    QCOMPARE(*readGpl(writeGpl(doc.palette())), clean);
}

QTEST_GUILESS_MAIN(TestPalette)
#include "tst_palette.moc"
