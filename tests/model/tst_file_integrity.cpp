// Format version 2: a CRC-32C after every section. Version-1 files (a fixture written before
// the change) still open; every single flipped bit is found; a damaged file is reported as
// damaged and "open anyway" (recoverFinbook) gets back what is still readable.
#include "tst_file_sample.h"

#include <QRandomGenerator>

#include <set>

using namespace finbook::model;
using namespace file_test;

namespace {
const QString kDataDir = QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data");

// The recovered document must be a valid one: it saves, and opens strictly again.
bool savesAndReopens(LoadedDocument &doc)
{
    Document d;
    adoptLoadedDocument(d, std::move(doc));
    auto again = readFinbook(serializeFinbook(d));
    if (!again)
        qWarning("recovered document does not reopen: %s", qPrintable(again.error().message));
    return bool(again);
}

// The same frames and objects, holds aside.
void compareGroupsOf(std::vector<Frame> actual, const std::vector<Frame> &expected)
{
    QCOMPARE(actual.size(), expected.size());
    for (std::size_t f = 0; f < actual.size(); ++f)
        actual[f].hold = expected[f].hold;
    compareFrames(actual, expected);
}

int framesOf(const QByteArray &bytes)
{
    auto loaded = readFinbook(bytes);
    return loaded ? int(loaded->frames.size()) : -1;
}
} // namespace

class TestFileIntegrity : public QObject {
    Q_OBJECT
private slots:
    void crc32cKnownAnswer();
    void everySectionCarriesItsChecksum();
    void versionOneFixtureOpens();
    void versionOneExampleOpensAsTheBundledOne();
    void everySingleBitFlipIsFound();
    void damagedSectionIsReportedAsDamaged();
    void recoverGetsBackWhatIsReadable();
    void recoverCutOffFile();
    void recoverSkipsBadRecords();
    void recoverFindsSectionsAfterDamagedHeader();
    void recoverRepairsIds();
    void recoverGivesNewIdsWhenTheFileUsesTheLargest();
    void recoverNeverCrashesAndGivesValidDocuments();
    void ancillarySectionsAreSkippedAndReadable();
};

void TestFileIntegrity::crc32cKnownAnswer()
{
    // RFC 3720 (iSCSI), appendix B.4, and the classic check value.
    QCOMPARE(io::crc32c(0, "123456789", 9), 0xe3069283u);
    const QByteArray zeros(32, '\0');
    QCOMPARE(io::crc32c(0, zeros.constData(), 32), 0x8a9136aau);
    const QByteArray ones(32, '\xff');
    QCOMPARE(io::crc32c(0, ones.constData(), 32), 0x62a8ab43u);
    // Continuing over pieces gives the checksum of the whole.
    QByteArray text(1000, '\0');
    for (int i = 0; i < text.size(); ++i)
        text[i] = char(i * 31 + 7);
    const quint32 whole = io::crc32c(0, text.constData(), std::size_t(text.size()));
    for (int cut : {1, 7, 8, 9, 500, 999})
        QCOMPARE(io::crc32c(io::crc32c(0, text.constData(), std::size_t(cut)),
                            text.constData() + cut, std::size_t(text.size() - cut)),
                 whole);
}

void TestFileIntegrity::everySectionCarriesItsChecksum()
{
    const QByteArray bytes = validBytes();
    QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 8), kFinbookFormatVersion);
    QVERIFY(kFinbookFormatVersion >= 2u); // checksums from format 2 on
    qsizetype at = 12;
    QStringList tags;
    while (at < bytes.size()) {
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        const qsizetype end = at + 12 + qsizetype(length);
        QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + end),
                 io::crc32c(0, bytes.constData() + at, std::size_t(end - at)));
        tags << QString::fromLatin1(bytes.mid(at, 4));
        at = end + 4;
    }
    QCOMPARE(at, bytes.size());
    QCOMPARE(tags, (QStringList{"DOCU", "STRK", "POSE", "FRAM", "LAYR", "FEND"}));
}

void TestFileIntegrity::versionOneFixtureOpens()
{
    const QByteArray v1 = fileBytes(kDataDir + QStringLiteral("/format_v1_sample.finbook"));
    QVERIFY(!v1.isEmpty());
    QCOMPARE(qFromLittleEndian<quint32>(v1.constData() + 8), 1u);
    auto loaded = readFinbook(v1);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->formatVersion, 1u);
    Document sample;
    buildSample(sample);
    compareFrames(loaded->frames, sample.frames());
    QCOMPARE(loaded->settings, sample.settings());
    // Saved again, it is today's format with the same content.
    // The layer a version-1 file opens as takes the file's next free id: compared without it.
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(reopened.layerCount(), 1);
    QCOMPARE(serializeFinbook(reopened.frames(), reopened.settings()),
             serializeFinbook(sample.frames(), sample.settings()));
    // A version-1 file has no checksums to check: a flipped point bit still loads, as it did.
    QByteArray flipped = v1;
    flipped[sectionPayload(v1, "STRK") + 20] ^= 0x01;
    QVERIFY(readFinbook(flipped));
}

void TestFileIntegrity::versionOneExampleOpensAsTheBundledOne()
{
    Document old, bundled;
    QVERIFY(!openFinbook(old, kDataDir + QStringLiteral("/walk_v1.finbook")));
    QVERIFY(!openFinbook(bundled,
                         QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook")));
    // The old file is one layer (its id the file's next free id); its drawings are the walk
    // cycle's layer of today's example scene, which opens on that layer.
    QCOMPARE(old.layerCount(), 1);
    QCOMPARE(bundled.currentLayer().properties.name, QStringLiteral("Walk"));
    QCOMPARE(serializeFinbook(old.frames(), old.settings()),
             serializeFinbook(bundled.frames(), bundled.settings()));
}

void TestFileIntegrity::everySingleBitFlipIsFound()
{
    const QByteArray valid = validBytes();
    int loaded = 0, damaged = 0;
    for (qsizetype at = 0; at < valid.size(); ++at)
        for (int bit = 0; bit < 8; ++bit) {
            QByteArray bytes = valid;
            bytes[at] = char(bytes[at] ^ (1 << bit));
            auto result = readFinbook(bytes);
            if (result)
                ++loaded;
            else if (result.error().code == FileErrorCode::Damaged)
                ++damaged;
        }
    qInfo("%lld single-bit flips: %d loaded, %d reported as damaged", valid.size() * 8LL, loaded,
          damaged);
    QCOMPARE(loaded, 0);
    QVERIFY(damaged > valid.size() * 8 * 9 / 10); // the rest hit the header or a length
}

void TestFileIntegrity::damagedSectionIsReportedAsDamaged()
{
    QByteArray bytes = validBytes();
    bytes[sectionPayload(bytes, "STRK") + 30] ^= 0x10; // inside a point of stroke data 1
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::Damaged);
    QVERIFY2(message.contains(QLatin1String("section STRK"), Qt::CaseInsensitive) &&
                 message.contains(QLatin1String("checksum")) &&
                 message.contains(QLatin1String("still readable")),
             qPrintable(message));
    QVERIFY(isRecoverable(FileErrorCode::Damaged));
    QVERIFY(!isRecoverable(FileErrorCode::NewerVersion));
}

void TestFileIntegrity::recoverGetsBackWhatIsReadable()
{
    const QByteArray valid = validBytes();
    QByteArray bytes = valid;
    bytes[sectionPayload(bytes, "STRK") + 30] ^= 0x10;
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY2(recovered, recovered ? "" : qPrintable(recovered.error().message));
    QVERIFY(!problems.isEmpty());
    QVERIFY2(problems.join(' ').contains(QLatin1String("checksum")),
             qPrintable(problems.join('|')));
    Document sample;
    buildSample(sample);
    // Everything is there; only the one point moved by the flipped bit differs.
    QCOMPARE(recovered->frames.size(), sample.frames().size());
    QCOMPARE(recovered->frames[0].groups.size(), sample.frameAt(0).groups.size());
    QVERIFY(savesAndReopens(*recovered));
    // An undamaged file recovers to exactly what it holds, with no problem.
    auto clean = recoverFinbook(valid, &problems);
    QVERIFY(clean);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join('|')));
    compareFrames(clean->frames, sample.frames());
}

void TestFileIntegrity::recoverCutOffFile()
{
    Document doc;
    buildSample(doc);
    // Many frames, so a cut in the middle of the frame list leaves some whole.
    std::vector<Frame> frames;
    Id next = doc.nextId() + 100;
    for (int copy = 0; copy < 10; ++copy)
        for (Frame f : doc.frames()) {
            f.id = next++;
            for (StrokeGroup &g : f.groups) {
                g.id = next++;
                for (Stroke &s : g.strokes)
                    s.id = next++;
                for (Pin &p : g.rig.pins)
                    p.id = next++;
            }
            frames.push_back(f);
        }
    Document big;
    big.reset(std::move(frames), doc.settings(), next);
    const QByteArray whole = serializeFinbook(big);
    const qsizetype framesAt = sectionPayload(whole, "FRAM");
    const QByteArray cut = whole.left(framesAt + (whole.size() - framesAt) / 2);
    QCOMPARE(errorOf(cut), FileErrorCode::Truncated);
    QStringList problems;
    auto recovered = recoverFinbook(cut, &problems);
    QVERIFY2(recovered, recovered ? "" : qPrintable(recovered.error().message));
    QVERIFY(recovered->frames.size() >= 10 && recovered->frames.size() < 30);
    QVERIFY2(problems.join(' ').contains(QLatin1String("ends")), qPrintable(problems.join('|')));
    for (std::size_t f = 0; f < recovered->frames.size(); ++f)
        QCOMPARE(recovered->frames[f].id, big.frameAt(int(f)).id);
    QVERIFY(savesAndReopens(*recovered));
}

void TestFileIntegrity::recoverSkipsBadRecords()
{
    QByteArray bytes = validBytes();
    // Frame 2's object count claims far more than the record holds; the hold of frame 1 is 0.
    const qsizetype frames = sectionPayload(bytes, "FRAM");
    const qsizetype frame1 = frames + 4;
    const quint32 frame1Length = qFromLittleEndian<quint32>(bytes.constData() + frame1);
    const qsizetype frame2 = frame1 + 4 + frame1Length;
    putU32(bytes, frame2 + 4 + 12, 0x00ffffffu);
    putU32(bytes, frame1 + 4 + 8, 0);
    refreshChecksums(bytes);
    QVERIFY(!readFinbook(bytes));
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY2(recovered, recovered ? "" : qPrintable(recovered.error().message));
    Document sample;
    buildSample(sample);
    compareGroupsOf(recovered->frames, sample.frames()); // every object read as it was
    QCOMPARE(recovered->frames[0].hold, 1);              // the hold of 0 got a value it may have
    QVERIFY(problems.size() >= 2);
    QVERIFY2(problems.join(' ').contains(QLatin1String("claims")), qPrintable(problems.join('|')));
    QVERIFY(savesAndReopens(*recovered));
}

void TestFileIntegrity::recoverFindsSectionsAfterDamagedHeader()
{
    QByteArray bytes = validBytes();
    // The stroke table's section header is overwritten: its tag and length are garbage.
    const qsizetype strokes = sectionPayload(bytes, "STRK") - 12;
    for (int i = 0; i < 12; ++i)
        bytes[strokes + i] = char(0xa5);
    QVERIFY(!readFinbook(bytes));
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY2(recovered, recovered ? "" : qPrintable(recovered.error().message));
    // The document settings and the frames are found; strokes lost with their table go.
    Document sample;
    buildSample(sample);
    QCOMPARE(recovered->settings, sample.settings());
    QCOMPARE(recovered->frames.size(), sample.frames().size());
    QVERIFY(recovered->frames[0].groups[0].strokes.empty());
    QVERIFY2(problems.join(' ').contains(QLatin1String("damaged bytes")),
             qPrintable(problems.join('|')));
    QVERIFY(savesAndReopens(*recovered));
}

void TestFileIntegrity::recoverRepairsIds()
{
    Document doc;
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    frames[2].groups[1].strokes[0].id = frames[0].id; // used twice
    frames[1].groups[0].id = kMaxId + 5;              // too large
    Document bad;
    bad.reset(std::move(frames), doc.settings(), doc.nextId());
    const QByteArray bytes = serializeFinbook(bad);
    QCOMPARE(errorOf(bytes), FileErrorCode::BadValue);
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered);
    QVERIFY2(problems.join(' ').contains(QLatin1String("new ones")),
             qPrintable(problems.join('|')));
    QVERIFY(recovered->frames[1].groups[0].id <= kMaxId);
    QVERIFY(recovered->frames[2].groups[1].strokes[0].id != recovered->frames[0].id);
    QVERIFY(recovered->nextId <= kMaxId + 1);
    QVERIFY(savesAndReopens(*recovered));
}

void TestFileIntegrity::recoverGivesNewIdsWhenTheFileUsesTheLargest()
{
    // A damaged file whose object holds the largest id there is (found by finbook-fuzz): the
    // ids recovery gives (a repeated one, the layers') cannot go above it, so they come from
    // below, unused, and the recovered document saves and opens again.
    Document doc;
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    frames[0].groups[0].id = kMaxId;
    frames[2].groups[1].strokes[0].id = frames[0].id; // used twice
    Document bad;
    bad.reset(std::move(frames), doc.settings(), kMaxId + 1);
    const QByteArray bytes = serializeFinbook(bad);
    QCOMPARE(errorOf(bytes), FileErrorCode::BadValue);
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered);
    QCOMPARE(recovered->frames[0].groups[0].id, kMaxId);
    std::set<Id> ids;
    std::size_t count = 0;
    for (const Frame &f : recovered->frames) {
        ids.insert(f.id);
        ++count;
        for (const StrokeGroup &g : f.groups) {
            ids.insert(g.id);
            ++count;
            for (const Stroke &st : g.strokes) {
                ids.insert(st.id);
                ++count;
            }
        }
    }
    for (const LoadedLayer &l : recovered->layers) {
        QVERIFY(l.id != kNoId && l.id <= kMaxId);
        ids.insert(l.id);
        ++count;
    }
    QCOMPARE(ids.size(), count); // all different
    QVERIFY(*ids.rbegin() <= kMaxId);
    QVERIFY(recovered->nextId <= kMaxId + 1);
    QVERIFY(savesAndReopens(*recovered));
    // A document read without its layer list (a file from before layers, or one whose list
    // was lost) gets one layer; with the ids used up to the largest, its id comes from below.
    LoadedDocument old;
    old.frames = doc.frames();
    old.frames[0].groups[0].id = kMaxId;
    old.nextId = kMaxId + 1;
    Document opened;
    adoptLoadedDocument(opened, old);
    QCOMPARE(opened.layers().size(), std::size_t(1));
    const Id layer = opened.layers().front().id;
    QVERIFY(layer != kNoId && layer <= kMaxId);
    for (const Frame &f : opened.frames()) {
        QVERIFY(f.id != layer);
        for (const StrokeGroup &g : f.groups)
            QVERIFY(g.id != layer);
    }
    QVERIFY(savesAndReopens(old));
}

void TestFileIntegrity::recoverNeverCrashesAndGivesValidDocuments()
{
    const QByteArray valid = validBytes();
    const qsizetype frames = sectionPayload(valid, "FRAM") - 12;
    QRandomGenerator random(20241123);
    int recovered = 0, oneByte = 0, oneByteRecovered = 0;
    for (int round = 0; round < 4000; ++round) {
        QByteArray bytes = valid;
        // Half the rounds change one byte anywhere after the header; the rest do up to twelve
        // changes, cuts and removals.
        const bool single = round % 2 == 0;
        const int mutations = single ? 1 : 1 + int(random.bounded(12));
        bool keptFrames = true;
        for (int m = 0; m < mutations && bytes.size() > 12; ++m) {
            const qsizetype at = 12 + random.bounded(qint64(bytes.size() - 12));
            switch (single ? 0 : random.bounded(5)) {
            case 0:
                bytes[at] = char(bytes[at] ^ (1 + random.bounded(255)));
                break;
            case 1:
                bytes[at] = char(bytes[at] ^ (1 << random.bounded(8)));
                break;
            case 2:
                bytes.truncate(at);
                keptFrames = keptFrames && at > frames + 40;
                break;
            case 3:
                bytes.remove(at, 1 + random.bounded(16));
                break;
            default:
                bytes[at] = char(0xff);
                break;
            }
        }
        QStringList problems;
        auto result = recoverFinbook(bytes, &problems);
        oneByte += single;
        if (!result) {
            QVERIFY(!result.error().message.isEmpty());
            if (single && qEnvironmentVariableIsSet("FINBOOK_TEST_VERBOSE"))
                qInfo("%s", qPrintable(result.error().message.left(160)));
            continue;
        }
        ++recovered;
        oneByteRecovered += single;
        Q_UNUSED(keptFrames);
        QVERIFY(savesAndReopens(*result));
    }
    qInfo("recover: %d of 4000 damaged files gave a document back; %d of %d with one byte "
          "changed",
          recovered, oneByteRecovered, oneByte);
    // One changed byte loses at most the record it is in: the document comes back.
    QVERIFY(oneByteRecovered >= oneByte * 95 / 100);
}

void TestFileIntegrity::ancillarySectionsAreSkippedAndReadable()
{
    Document doc;
    buildSample(doc);
    const QByteArray plain = serializeFinbook(doc);
    const QByteArray extra =
        serializeFinbook(doc.frames(), doc.settings(), {{"rcvy", QByteArray("{\"a\":1}")}});
    QVERIFY(extra.size() > plain.size());
    auto loaded = readFinbook(extra);
    QVERIFY(loaded);
    compareFrames(loaded->frames, doc.frames());
    QCOMPARE(readAncillarySection(extra, "rcvy"), std::optional<QByteArray>("{\"a\":1}"));
    QCOMPARE(readAncillarySection(plain, "rcvy"), std::nullopt);
    QByteArray damaged = extra;
    damaged[damaged.size() - 30] ^= 0x01; // inside the rcvy payload
    QCOMPARE(readAncillarySection(damaged, "rcvy"), std::nullopt);
    QCOMPARE(framesOf(plain), 3);
}

QTEST_GUILESS_MAIN(TestFileIntegrity)
#include "tst_file_integrity.moc"
