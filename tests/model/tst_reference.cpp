// The reference layer with a picture: import, undo, lock, save/reopen byte-identical, hostile
// files refused with nothing lost, export only with "Include reference".
#include "hostile_media.h"
#include "reference_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/reference/reference_commands.h>

#include <QElapsedTimer>
#include <QFile>
#include <QTest>
#include <QtEndian>

using namespace finbook;
using namespace finbook::model;

namespace {

// A document with one frame holding one short black stroke near the top-left corner.
void makeDrawing(Document &doc)
{
    DocumentSettings s;
    s.canvasSize = QSize(160, 120);
    s.background = 0xffffffff;
    Frame frame;
    frame.id = doc.allocateId();
    StrokeGroup group;
    group.id = doc.allocateId();
    auto data = std::make_shared<StrokeData>();
    data->color = 0xff000000;
    data->width = 4.0f;
    data->points = {{10.0f, 10.0f, 1.0f}, {30.0f, 10.0f, 1.0f}};
    group.strokes.push_back(Stroke{doc.allocateId(), data});
    frame.groups.push_back(group);
    std::vector<Frame> frames;
    frames.push_back(frame);
    doc.reset(std::move(frames), s, doc.nextId());
}

class TestReference : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    Reference imported(Document &doc)
    {
        auto r = importReferenceFile(test::writeTwoColourPng(m_dir.path()),
                                     QSizeF(doc.settings().canvasSize));
        if (!r)
            qWarning() << r.error();
        return r ? *r : Reference();
    }

private slots:
    // Issue 47: SVG references are drawn at a bounded cost, text and all (this test runs with
    // a QGuiApplication, as the editor and `finbook export --include-reference` do).
    void svgReferencesAreBounded()
    {
        auto text = ReferenceMedia::open(ReferenceKind::Image, hostile_media::svgWithText());
        QVERIFY2(text, text ? "" : qPrintable(text.error()));
        QCOMPARE((*text)->size(), QSize(120, 80));
        QCOMPARE((*text)->frame(0).pixel(5, 5), qRgb(0xff, 0xd0, 0xd0));
        struct Case {
            const char *name;
            QByteArray bytes;
            QString says;
        };
        const Case cases[] = {
            {"use bomb", hostile_media::useBomb(), QStringLiteral("100,000")},
            {"use loop", hostile_media::useLoop(), QStringLiteral("loop")},
            {"slow", hostile_media::slowSvg(), QStringLiteral("too long")},
            {"entities",
             "<?xml version=\"1.0\"?><!DOCTYPE svg [<!ENTITY a \"aaaaaaaaaa\">]>"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"9\" height=\"9\">"
             "<text>&a;</text></svg>",
             QStringLiteral("entities")},
        };
        for (const Case &c : cases) {
            QElapsedTimer clock;
            clock.start();
            const auto media = ReferenceMedia::open(ReferenceKind::Image, c.bytes);
            qInfo("%s SVG (%lld bytes): %s in %lld ms", c.name, qint64(c.bytes.size()),
                  media ? "drawn" : qPrintable(media.error()), clock.elapsed());
            QVERIFY2(!media, c.name);
            QVERIFY2(media.error().contains(c.says), qPrintable(media.error()));
            // 2 s of CPU at most; the wall clock of a busy machine is given room. Unbounded,
            // the slow one paints 50 billion pixels.
            QVERIFY2(clock.elapsed() < 20000, c.name);
        }
        // A picture that says it is 100,000 px wide is drawn 4,096 px wide.
        const QByteArray huge =
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100000\" height=\"50000\">"
            "<rect width=\"100000\" height=\"50000\" fill=\"#00ff00\"/></svg>";
        const auto big = ReferenceMedia::open(ReferenceKind::Image, huge);
        QVERIFY2(big, big ? "" : qPrintable(big.error()));
        QCOMPARE((*big)->size(), QSize(4096, 2048));
        QCOMPARE((*big)->frame(0).pixel(4000, 2000), qRgb(0, 255, 0));
    }

    void importFitsTheCanvasAndUndoes()
    {
        Document doc;
        makeDrawing(doc);
        const QByteArray before = serializeFinbook(doc);
        const Reference r = imported(doc);
        QCOMPARE(r.kind, ReferenceKind::Image);
        QCOMPARE(r.mediaSize, QSizeF(80, 60));
        QCOMPARE(r.center, QPointF(80, 60));
        QCOMPARE(r.scale, 2.0); // 80×60 fits 160×120 at 2×
        doc.undoStack()->push(importReferenceCommand(&doc, r).release());
        QCOMPARE(doc.referenceLayer().reference(), r);
        QVERIFY(doc.referenceLayer().media());
        QCOMPARE(doc.referenceLayer().pictureAt(0).size(), QSize(80, 60));
        doc.undoStack()->undo();
        QVERIFY(doc.referenceLayer().isEmpty());
        QCOMPARE(serializeFinbook(doc), before);
        doc.undoStack()->redo();
        QCOMPARE(doc.referenceLayer().reference(), r);
    }

    void editsUndoExactlyAndMerge()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        const Reference start = doc.referenceLayer().reference();
        for (double opacity : {0.2, 0.3, 0.4}) {
            Reference r = doc.referenceLayer().reference();
            r.opacity = opacity;
            doc.undoStack()->push(editReferenceCommand(&doc, r, ReferenceEdit::Opacity).release());
        }
        QCOMPARE(doc.undoStack()->count(), 2); // the opacity steps merged
        Reference moved = doc.referenceLayer().reference();
        moved.center += QPointF(7.25, -3.5);
        moved.scale = 0.75;
        moved.rotation = 33.0;
        doc.undoStack()->push(editReferenceCommand(&doc, moved, ReferenceEdit::Place).release());
        QCOMPARE(doc.referenceLayer().reference(), moved);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.referenceLayer().reference(), start);
    }

    void lockedReferenceDoesNotMove()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        Reference locked = doc.referenceLayer().reference();
        locked.locked = true;
        doc.undoStack()->push(editReferenceCommand(&doc, locked, ReferenceEdit::Locked).release());
        Reference moved = locked;
        moved.center += QPointF(10, 0);
        QVERIFY(!editReferenceCommand(&doc, moved, ReferenceEdit::Place));
        Reference faded = locked;
        faded.opacity = 0.9;
        QVERIFY(editReferenceCommand(&doc, faded, ReferenceEdit::Opacity));
    }

    void rejectsValuesOutOfRange()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        Reference bad = doc.referenceLayer().reference();
        bad.scale = std::nan("");
        QVERIFY(!editReferenceCommand(&doc, bad, ReferenceEdit::Scale));
        bad = doc.referenceLayer().reference();
        bad.opacity = 1.5;
        QVERIFY(!editReferenceCommand(&doc, bad, ReferenceEdit::Opacity));
    }

    void saveReopenIsByteIdentical()
    {
        Document doc;
        makeDrawing(doc);
        Reference r = imported(doc);
        r.rotation = 12.5;
        r.locked = true;
        doc.undoStack()->push(importReferenceCommand(&doc, r).release());
        const QString path = m_dir.filePath(QStringLiteral("with-reference.finbook"));
        QVERIFY(!saveFinbook(doc, path));
        Document reopened;
        QVERIFY(!openFinbook(reopened, path));
        QCOMPARE(reopened.referenceLayer().reference(), r);
        QCOMPARE(serializeFinbook(reopened), serializeFinbook(doc));
        QFile png(test::writeTwoColourPng(m_dir.path()));
        QVERIFY(png.open(QIODevice::ReadOnly));
        QCOMPARE(reopened.referenceLayer().reference().bytes, png.readAll());
        // The bytes are in the file once.
        QFile saved(path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QCOMPARE(saved.readAll().count(r.bytes), 1);
    }

    void damagedSectionIsRefusedThenRecovered()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        QByteArray bytes = serializeFinbook(doc);
        const qsizetype at = bytes.indexOf("refr");
        QVERIFY(at > 0);
        bytes[at + 40] = char(bytes[at + 40] ^ 0x5a); // inside the section: its CRC fails
        const auto read = readFinbook(bytes);
        QVERIFY(!read);
        QCOMPARE(read.error().code, FileErrorCode::Damaged);
        QStringList problems;
        const auto recovered = recoverFinbook(bytes, &problems);
        QVERIFY(recovered);
        QCOMPARE(recovered->frames.size(), std::size_t(1));
    }

    void hostileLengthsAreRefused()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        const QByteArray good = serializeFinbook(doc);
        // A well-formed section (right CRC) whose media length claims more than there is.
        Reference r = doc.referenceLayer().reference();
        QByteArray payload;
        {
            Document other;
            makeDrawing(other);
            other.referenceLayer().setReference(r);
            const QByteArray all = serializeFinbook(other);
            const auto section = readAncillarySection(all, "refr");
            QVERIFY(section);
            payload = *section;
        }
        const qsizetype lengthAt = payload.size() - r.bytes.size() - 8;
        qToLittleEndian<quint64>(quint64(1) << 40, payload.data() + lengthAt);
        const QByteArray hostile =
            serializeFinbook(doc.frames(), doc.settings(), {{{'r', 'e', 'f', 'r', '\0'}, payload}});
        const auto read = readFinbook(hostile);
        QVERIFY(!read);
        QVERIFY(!read.error().message.isEmpty());
        // A NaN scale.
        payload = *readAncillarySection(good, "refr");
        qToLittleEndian<quint64>(0x7ff8000000000000ull, payload.data() + 2 + 4 * 8);
        QVERIFY(!readFinbook(serializeFinbook(doc.frames(), doc.settings(),
                                              {{{'r', 'e', 'f', 'r', '\0'}, payload}})));
    }

    void truncatedImageIsRefusedAndNothingChanges()
    {
        Document doc;
        makeDrawing(doc);
        QFile png(test::writeTwoColourPng(m_dir.path()));
        QVERIFY(png.open(QIODevice::ReadOnly));
        const QByteArray whole = png.readAll();
        const QString cut = m_dir.filePath(QStringLiteral("cut.png"));
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(whole.left(40));
        out.close();
        const auto refused = importReferenceFile(cut, QSizeF(160, 120));
        QVERIFY(!refused);
        QVERIFY(refused.error().contains(QStringLiteral("cut.png")));
        const QString junk = m_dir.filePath(QStringLiteral("junk.mp4"));
        QFile j(junk);
        QVERIFY(j.open(QIODevice::WriteOnly));
        j.write(QByteArray(5000, '\x17'));
        j.close();
        QVERIFY(!importReferenceFile(junk, QSizeF(160, 120)));
        QVERIFY(!importReferenceFile(m_dir.filePath(QStringLiteral("missing.png")), {}));
        QVERIFY(doc.referenceLayer().isEmpty());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void exportIncludesItOnlyWhenAsked()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        Reference opaque = doc.referenceLayer().reference();
        opaque.opacity = 1.0;
        doc.undoStack()->push(editReferenceCommand(&doc, opaque, ReferenceEdit::Opacity).release());
        const auto exportOnce = [&](bool include) {
            ExportOptions o;
            o.format = ExportFormat::PngSequence;
            o.target = m_dir.filePath(include ? QStringLiteral("with") : QStringLiteral("without"));
            o.includeReference = include;
            const auto result = exportAnimation(exportSource(doc), o);
            return result && !result->files.isEmpty() ? QImage(result->files.first()) : QImage();
        };
        const QImage without = exportOnce(false);
        const QImage with = exportOnce(true);
        QCOMPARE(without.pixel(40, 90), qRgb(255, 255, 255));
        QCOMPARE(with.pixel(40, 90), qRgb(255, 0, 0));
        QCOMPARE(with.pixel(120, 90), qRgb(0, 0, 255));
        QCOMPARE(with.pixel(20, 10), qRgb(0, 0, 0)); // the stroke lies over it
    }

    void hiddenReferenceIsNotShown()
    {
        Document doc;
        makeDrawing(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported(doc)).release());
        Reference hidden = doc.referenceLayer().reference();
        hidden.visible = false;
        doc.undoStack()->push(editReferenceCommand(&doc, hidden, ReferenceEdit::Visible).release());
        QVERIFY(doc.referenceLayer().pictureAt(0).isNull());
        // The reference is no object: the frame's objects are as they were.
        QCOMPARE(doc.frameAt(0).groups.size(), std::size_t(1));
    }
};

} // namespace

QTEST_MAIN(TestReference)
#include "tst_reference.moc"
