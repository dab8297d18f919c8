// An image sequence as the reference: the numbered run found from one picture, one picture per
// frame, undo, save/reopen byte-identical with each picture stored once, an older reader's view
// (the first picture as a still), hostile and truncated entries refused with nothing lost.
#include "reference_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/reference/reference_commands.h>

#include <QFile>
#include <QTest>
#include <QtEndian>

using namespace finbook;
using namespace finbook::model;

namespace {

const QRgb kColours[] = {qRgb(255, 0, 0), qRgb(0, 160, 0), qRgb(0, 0, 255)};

QString writePng(const QString &folder, const QString &name, QRgb colour)
{
    QImage image(40, 30, QImage::Format_RGB32);
    image.fill(colour);
    const QString path = QDir(folder).filePath(name);
    image.save(path);
    return path;
}

QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// A document of three one-tick frames (plus a held fourth) on a 160×120 canvas.
void makeFrames(Document &doc)
{
    DocumentSettings s;
    s.canvasSize = QSize(160, 120);
    std::vector<Frame> frames;
    for (int i = 0; i < 4; ++i) {
        Frame f;
        f.id = doc.allocateId();
        f.hold = i == 3 ? 2 : 1;
        frames.push_back(f);
    }
    doc.reset(std::move(frames), s, doc.nextId());
}

// The top-left pixel of the picture shown under frame `index`.
QRgb shownAt(const Document &doc, int index)
{
    const QImage picture = doc.referenceLayer().pictureAt(index);
    return picture.isNull() ? 0 : picture.pixel(0, 0);
}

class TestReferenceSequence : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QStringList m_run;

    Reference imported()
    {
        auto r = importReferenceSequence(m_run, QSizeF(160, 120));
        if (!r)
            qWarning() << r.error();
        return r ? *r : Reference();
    }

private slots:
    void initTestCase()
    {
        for (int i = 0; i < 3; ++i)
            m_run << writePng(m_dir.path(),
                              QStringLiteral("shot_%1.png").arg(i + 1, 4, 10, QLatin1Char('0')),
                              kColours[i]);
        // Not of the run: a gap after it, another prefix, another extension, unpadded.
        writePng(m_dir.path(), QStringLiteral("shot_0005.png"), qRgb(1, 1, 1));
        writePng(m_dir.path(), QStringLiteral("take_0002.png"), qRgb(1, 1, 1));
        writePng(m_dir.path(), QStringLiteral("shot_0002.jpg"), qRgb(1, 1, 1));
        writePng(m_dir.path(), QStringLiteral("shot_2.png"), qRgb(1, 1, 1));
    }

    void oneFileOfANumberedRunFindsTheRun()
    {
        QCOMPARE(numberedSequence(m_run[1]), m_run);
        QCOMPARE(numberedSequence(m_run[0]), m_run);
        const QString alone = m_dir.filePath(QStringLiteral("take_0002.png"));
        QCOMPARE(numberedSequence(alone), QStringList{alone});
        const QString plain = writePng(m_dir.path(), QStringLiteral("plain.png"), 0);
        QCOMPARE(numberedSequence(plain), QStringList{plain});
    }

    void eachFrameShowsItsPictureAndUndoes()
    {
        Document doc;
        makeFrames(doc);
        const QByteArray before = serializeFinbook(doc);
        const Reference r = imported();
        QCOMPARE(r.kind, ReferenceKind::Sequence);
        QCOMPARE(r.pictures.size(), 3);
        QCOMPARE(r.mediaSize, QSizeF(40, 30));
        QCOMPARE(r.scale, 4.0); // 40×30 fits 160×120 at 4×
        doc.undoStack()->push(importReferenceCommand(&doc, r).release());
        for (int k = 0; k < 3; ++k)
            QCOMPARE(shownAt(doc, k), kColours[k]);
        QCOMPARE(shownAt(doc, 3), kColours[2]); // past the end: the last picture stays
        // Half the document's rate: each picture held two ticks.
        Reference slow = r;
        slow.rate = doc.settings().fps / 2.0;
        doc.undoStack()->push(editReferenceCommand(&doc, slow, ReferenceEdit::Rate).release());
        QCOMPARE(shownAt(doc, 1), kColours[0]);
        QCOMPARE(shownAt(doc, 2), kColours[1]);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(doc.referenceLayer().isEmpty());
        QCOMPARE(serializeFinbook(doc), before);
        doc.undoStack()->redo();
        QCOMPARE(doc.referenceLayer().reference(), r);
        QCOMPARE(shownAt(doc, 2), kColours[2]);
    }

    void decodesOnDemandWithinTheCache()
    {
        const Reference r = imported();
        auto media = *ReferenceMedia::open(r);
        QCOMPARE(media->frameCount(), qint64(3));
        QVERIFY(media->cachedFrame(2).isNull()); // only the first is decoded on opening
        media->setCacheLimit(1);                 // at least one picture is always kept
        QCOMPARE(media->frame(2).pixel(0, 0), kColours[2]);
        QCOMPARE(media->frame(1).pixel(0, 0), kColours[1]);
        QVERIFY(media->cachedFrame(2).isNull());
        QCOMPARE(media->cacheBytes(), media->frame(1).sizeInBytes());
    }

    void saveReopenIsByteIdenticalWithEachPictureOnce()
    {
        Document doc;
        makeFrames(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported()).release());
        const QString path = m_dir.filePath(QStringLiteral("sequence.finbook"));
        QVERIFY(!saveFinbook(doc, path));
        Document reopened;
        QVERIFY(!openFinbook(reopened, path));
        QCOMPARE(reopened.referenceLayer().reference(), doc.referenceLayer().reference());
        QCOMPARE(serializeFinbook(reopened), serializeFinbook(doc));
        const QByteArray saved = fileBytes(path);
        for (const QString &picture : m_run)
            QCOMPARE(saved.count(fileBytes(picture)), 1);
        for (int k = 0; k < 3; ++k)
            QCOMPARE(shownAt(reopened, k), kColours[k]);
    }

    void anOlderReaderSeesTheFirstPicture()
    {
        // What a Finbook that skips "rseq" reads: the refr section alone.
        Document doc;
        makeFrames(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported()).release());
        const QByteArray all = serializeFinbook(doc);
        const auto refr = readAncillarySection(all, "refr");
        QVERIFY(refr);
        QVERIFY(readAncillarySection(all, "rseq"));
        const auto older = readFinbook(
            serializeFinbook(doc.frames(), doc.settings(), {{{'r', 'e', 'f', 'r', '\0'}, *refr}}));
        QVERIFY(older);
        QCOMPARE(older->reference.kind, ReferenceKind::Image);
        QCOMPARE(older->reference.bytes, fileBytes(m_run[0]));
    }

    void hostileSequenceSectionsAreRefused()
    {
        Document doc;
        makeFrames(doc);
        doc.undoStack()->push(importReferenceCommand(&doc, imported()).release());
        const QByteArray all = serializeFinbook(doc);
        const QByteArray refr = *readAncillarySection(all, "refr");
        const QByteArray rseq = *readAncillarySection(all, "rseq");
        const auto withSections = [&](const QByteArray &first, const QByteArray &more) {
            std::vector<AncillarySection> extra;
            if (!first.isEmpty())
                extra.push_back({{'r', 'e', 'f', 'r', '\0'}, first});
            extra.push_back({{'r', 's', 'e', 'q', '\0'}, more});
            return serializeFinbook(doc.frames(), doc.settings(), extra);
        };
        QVERIFY(readFinbook(withSections(refr, rseq)));
        // A picture claiming more bytes than the section has (a well-formed CRC around it).
        QByteArray hostile = rseq;
        qToLittleEndian<quint64>(quint64(1) << 40, hostile.data() + 4);
        auto read = readFinbook(withSections(refr, hostile));
        QVERIFY(!read);
        QVERIFY(!read.error().message.isEmpty());
        // Recovering keeps the drawing and the first picture, and says what was left out.
        QStringList problems;
        const auto recovered = recoverFinbook(withSections(refr, hostile), &problems);
        QVERIFY(recovered);
        QCOMPARE(recovered->frames.size(), std::size_t(4));
        QCOMPARE(recovered->reference.kind, ReferenceKind::Image);
        QVERIFY(!problems.isEmpty());
        // A count no section could hold; pictures without the first; a zero count.
        hostile = rseq;
        qToLittleEndian<quint32>(0xffffffffu, hostile.data());
        QVERIFY(!readFinbook(withSections(refr, hostile)));
        QVERIFY(!readFinbook(withSections(QByteArray(), rseq)));
        QVERIFY(!readFinbook(withSections(refr, QByteArray(4, '\0'))));
        // Cut short: the last picture's bytes end early.
        QVERIFY(!readFinbook(withSections(refr, rseq.left(rseq.size() - 7))));
    }

    void aBrokenPictureRefusesTheImportAndNothingChanges()
    {
        Document doc;
        makeFrames(doc);
        const QString cut = m_dir.filePath(QStringLiteral("cut_0002.png"));
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(fileBytes(m_run[1]).left(60)); // past its header: it looks like a PNG
        out.close();
        const auto refused = importReferenceSequence({m_run[0], cut, m_run[2]}, QSizeF(160, 120));
        QVERIFY(!refused);
        QVERIFY(refused.error().contains(QStringLiteral("cut_0002.png")));
        QVERIFY(!importReferenceSequence({m_run[0], m_dir.filePath(QStringLiteral("gone.png"))},
                                         QSizeF(160, 120)));
        QVERIFY(doc.referenceLayer().isEmpty());
        QCOMPARE(doc.undoStack()->count(), 0);
    }
};

} // namespace

QTEST_MAIN(TestReferenceSequence)
#include "tst_reference_sequence.moc"
