// The .finbook reader against malformed input: every truncation, foreign files, out-of-range
// values, absurd counts, unknown sections and random mutations give a typed error, never a
// crash or a huge allocation.
#include "tst_file_sample.h"

#include <finbook/model/pins/pin_commands.h>

#include <QRandomGenerator>
#include <QTemporaryDir>

#include <limits>

using namespace finbook::model;
using namespace file_test;

class TestFileMalformed : public QObject {
    Q_OBJECT
private slots:
    void everyPrefixIsAnError();
    void foreignFilesAreNotFinbook();
    void invalidValuesAreRejected_data();
    void invalidValuesAreRejected();
    void badNameUtf8IsRejected();
    void meshDensityIsHeldToTheEditors();
    void newerVersionIsRefused();
    void flippedVersionBitsAreDamage();
    void flippedLengthsAreDamageNotTruncation();
    void absurdCountsAreRefused();
    void unknownSectionsAreSkippedOrRefused();
    void fuzzedFilesNeverCrash();
};

void TestFileMalformed::everyPrefixIsAnError()
{
    const QByteArray bytes = validBytes();
    QCOMPARE(errorOf(QByteArray()), FileErrorCode::NotFinbook);
    for (qsizetype n = 1; n < bytes.size(); ++n) {
        QString message;
        const FileErrorCode code = errorOf(bytes.left(n), &message);
        if (code != FileErrorCode::Truncated)
            QFAIL(qPrintable(
                QStringLiteral("prefix %1: code %2, %3").arg(n).arg(int(code)).arg(message)));
    }
    QVERIFY(readFinbook(bytes));
}

void TestFileMalformed::foreignFilesAreNotFinbook()
{
    QRandomGenerator random(7);
    QByteArray noise(4096, '\0');
    for (char &c : noise)
        c = char(random.bounded(256));
    const QByteArray png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    for (const QByteArray &bytes : {noise, png, QByteArray("hello, world\n")})
        QCOMPARE(errorOf(bytes), FileErrorCode::NotFinbook);
}

void TestFileMalformed::invalidValuesAreRejected_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("fps 0") << 0 << "frame rate 0";
    QTest::newRow("fps 61") << 1 << "frame rate 61";
    QTest::newRow("canvas 0") << 2 << "canvas size";
    QTest::newRow("hold 0") << 3 << "frame 2: the hold 0";
    QTest::newRow("NaN point") << 4
                               << "frame 1, object \"body\", stroke 2: point 3 has a non-finite";
    QTest::newRow("width 0") << 5 << "frame 1, object \"Ärm ✋\", stroke 1: the width 0";
    QTest::newRow("duplicate id") << 6
                                  << "frame 3, object \"odd\", stroke 1: the stroke has the id 1";
    QTest::newRow("zero id") << 7 << "frame 1, object 1: the object has no id";
    QTest::newRow("nextId low") << 8 << "next free id";
    QTest::newRow("pin NaN") << 9 << "frame 1, object \"body\": pin 2 has a non-finite";
    QTest::newRow("density") << 10 << "mesh density";
    QTest::newRow("play range") << 11 << "play range";
}

void TestFileMalformed::invalidValuesAreRejected()
{
    QFETCH(int, kind);
    QFETCH(QString, expected);
    Document doc;
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    DocumentSettings settings = doc.settings();
    Id nextId = doc.nextId();
    auto editPoints = [](Stroke &s, auto edit) {
        auto data = std::make_shared<StrokeData>(*s.data);
        edit(*data);
        s.data = data;
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    switch (kind) {
    case 0:
        settings.fps = 0;
        break;
    case 1:
        settings.fps = 61;
        break;
    case 2:
        settings.canvasSize = QSize(0, 100);
        break;
    case 3:
        frames[1].hold = 0;
        break;
    case 4:
        editPoints(frames[0].groups[0].strokes[1], [&](StrokeData &d) { d.points[2].x = nan; });
        break;
    case 5:
        editPoints(frames[0].groups[1].strokes[0], [](StrokeData &d) { d.width = 0; });
        break;
    case 6:
        frames[2].groups[1].strokes[0].id = 1;
        break;
    case 7:
        frames[0].groups[0].id = kNoId;
        break;
    case 8:
        nextId = 0;
        break;
    case 9:
        frames[0].groups[0].rig.pins[1].target.setY(double(nan));
        break;
    case 10:
        frames[1].groups[1].meshDensity = -1;
        break;
    case 11:
        settings.playStart = -3;
        break;
    }
    Document bad;
    bad.reset(std::move(frames), settings, nextId);
    QByteArray bytes = serializeFinbook(bad);
    if (kind == 8) // Document::reset and the writer both repair a low counter: patch it.
        qToLittleEndian<quint64>(1, bytes.data() + sectionPayload(bytes, "DOCU") + 25);
    refreshChecksums(bytes);
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
    QVERIFY2(message.contains(expected, Qt::CaseInsensitive), qPrintable(message));
}

// A mesh density the editor cannot set (it offers 0.25 to 4) is read as the nearest it can:
// a file asking for density 100 (work and memory grow with the square) costs what 4 costs.
void TestFileMalformed::meshDensityIsHeldToTheEditors()
{
    for (const auto &[stored, read] : {std::pair{100.0, kMaxMeshDensity}, std::pair{4.5, 4.0},
                                       std::pair{0.01, kMinMeshDensity}, std::pair{2.0, 2.0}}) {
        Document doc;
        buildSample(doc);
        std::vector<Frame> frames = doc.frames();
        frames[1].groups[1].meshDensity = stored;
        Document crafted;
        crafted.reset(std::move(frames), doc.settings(), doc.nextId());
        auto loaded = readFinbook(serializeFinbook(crafted));
        QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
        QCOMPARE(loaded->frames[1].groups[1].meshDensity, read);
    }
}

void TestFileMalformed::badNameUtf8IsRejected()
{
    QByteArray bytes = validBytes();
    const qsizetype at = bytes.indexOf("odd");
    QVERIFY(at > 0);
    bytes[at + 1] = char(0xc3); // a lead byte followed by an ASCII byte
    refreshChecksums(bytes);
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
    QVERIFY2(
        message.contains(QLatin1String("frame 3, object 2: the object name is not valid UTF-8"),
                         Qt::CaseInsensitive),
        qPrintable(message));
}

void TestFileMalformed::newerVersionIsRefused()
{
    QByteArray bytes = validBytes();
    putU32(bytes, 8, kFinbookFormatVersion + 1);
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::NewerVersion);
    QVERIFY2(message.contains(QLatin1String("newer")) && message.contains(QLatin1String("update")),
             qPrintable(message));
    putU32(bytes, 8, 0);
    QCOMPARE(errorOf(bytes), FileErrorCode::Damaged);
}

// One flipped bit in the version word: the next version or the one after may be a newer
// Finbook's file; a word that is no version any Finbook writes (say 7, 11, …, 2^31 + 3) is
// damaged. A flip onto an older version that exists is refused by its layout. That is said as
// damage (with "open anyway", which reads the file as the version its checksums show), not as
// "update".
void TestFileMalformed::flippedVersionBitsAreDamage()
{
    const QByteArray valid = validBytes();
    int newer = 0;
    for (int bit = 0; bit < 32; ++bit) {
        QByteArray bytes = valid;
        putU32(bytes, 8, kFinbookFormatVersion ^ (quint32(1) << bit));
        QString message;
        const FileErrorCode code = errorOf(bytes, &message);
        const quint32 version = kFinbookFormatVersion ^ (quint32(1) << bit);
        if (version > kFinbookFormatVersion && version <= kFinbookFormatVersion + 2) {
            QCOMPARE(code, FileErrorCode::NewerVersion);
            ++newer;
            continue;
        }
        if (version >= 1 && version < kFinbookFormatVersion) {
            // An older version that exists: the sections are then read by the older layout,
            // which the newer content does not fit, so the file is refused, never opened wrong.
            QVERIFY2(code != FileErrorCode::NewerVersion, qPrintable(message));
            continue;
        }
        QCOMPARE(code, FileErrorCode::Damaged);
        QVERIFY(isRecoverable(code));
        QVERIFY2(message.contains(QLatin1String("damaged")) &&
                     !message.contains(QLatin1String("newer")),
                 qPrintable(message));
        QStringList problems;
        const auto recovered = recoverFinbook(bytes, &problems);
        QVERIFY2(recovered, qPrintable(recovered ? QString() : recovered.error().message));
        QCOMPARE(recovered->frames.size(), readFinbook(valid)->frames.size());
        QCOMPARE(problems.size(), 1);
    }
    QVERIFY(newer <= 2); // only the next two versions are plausible (none for version 3)
    // From disk too: File > Open refuses it after its header; Open Anyway reads past it.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("flipped.finbook"));
    QByteArray bytes = valid;
    putU32(bytes, 8, kFinbookFormatVersion ^ 0x100u);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size());
    file.close();
    const auto refused = loadFinbook(path);
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, FileErrorCode::Damaged);
    QStringList problems;
    QVERIFY(loadFinbookRecovering(path, &problems));
    QCOMPARE(problems.size(), 1);
}

// A length that runs past the end of a file that is complete (it ends with its end marker) is
// damage, not an incomplete file; a record's length running past its section is damage too.
void TestFileMalformed::flippedLengthsAreDamageNotTruncation()
{
    const QByteArray valid = validBytes();
    const qsizetype frames = sectionPayload(valid, "FRAM");
    for (int bit = 20; bit < 64; bit += 7) {
        QByteArray bytes = valid;
        qToLittleEndian<quint64>(qFromLittleEndian<quint64>(bytes.constData() + frames - 8) ^
                                     (quint64(1) << bit),
                                 bytes.data() + frames - 8);
        QString message;
        QCOMPARE(errorOf(bytes, &message), FileErrorCode::Damaged);
        QVERIFY2(message.contains(QLatin1String("damaged")) &&
                     !message.contains(QLatin1String("incomplete")),
                 qPrintable(message));
    }
    // Cut short, the same file is incomplete.
    QCOMPARE(errorOf(valid.left(valid.size() - 40)), FileErrorCode::Truncated);
}

void TestFileMalformed::absurdCountsAreRefused()
{
    const QByteArray valid = validBytes();
    const qsizetype strokes = sectionPayload(valid, "STRK");
    const qsizetype frames = sectionPayload(valid, "FRAM");
    QVERIFY(strokes > 0 && frames > 0);
    for (qsizetype at : {strokes, strokes + 12, sectionPayload(valid, "POSE"), frames,
                         frames + 20 /* object count of frame 1 */}) {
        QByteArray bytes = valid;
        putU32(bytes, at, 0xffffffffu);
        refreshChecksums(bytes);
        QString message;
        QCOMPARE(errorOf(bytes, &message), FileErrorCode::TooLarge);
        QVERIFY(message.contains(QLatin1String("4294967295")));
    }
    // Lengths beyond what is there, in a complete file: damage (issue 25), not truncation.
    QByteArray bytes = valid;
    qToLittleEndian<quint64>(~quint64(0), bytes.data() + frames - 8);
    QCOMPARE(errorOf(bytes), FileErrorCode::Damaged);
    bytes = valid;
    putU32(bytes, frames + 4, 0x7fffffffu); // frame record length
    refreshChecksums(bytes);
    QCOMPARE(errorOf(bytes), FileErrorCode::BadValue);
}

void TestFileMalformed::unknownSectionsAreSkippedOrRefused()
{
    const QByteArray valid = validBytes();
    const qsizetype frames = sectionPayload(valid, "FRAM") - 12;
    auto withSection = [&](const char *tag) {
        return QByteArray(valid).insert(frames, sectionBytes(tag, "abc"));
    };
    auto ancillary = readFinbook(withSection("thmb"));
    QVERIFY(ancillary);
    QCOMPARE(errorOf(withSection("CAGE")), FileErrorCode::NewerVersion);
    QCOMPARE(errorOf(withSection("\x01\x02\x03\x04")), FileErrorCode::BadValue);
    QCOMPARE(errorOf(valid + QByteArray("x")), FileErrorCode::BadValue);
    QByteArray repeated = valid;
    repeated.insert(frames, valid.mid(12, sectionPayload(valid, "STRK") - 12 - 12));
    QCOMPARE(errorOf(repeated), FileErrorCode::BadValue);
}

void TestFileMalformed::fuzzedFilesNeverCrash()
{
    const QByteArray valid = validBytes();
    QRandomGenerator random(20240611);
    int loaded = 0;
    for (int round = 0; round < 2000; ++round) {
        QByteArray bytes = valid;
        const int mutations = 1 + int(random.bounded(8));
        for (int m = 0; m < mutations; ++m) {
            const qsizetype at = random.bounded(qint64(bytes.size()));
            switch (random.bounded(4)) {
            case 0:
                bytes[at] = char(random.bounded(256));
                break;
            case 1:
                bytes[at] = char(bytes[at] ^ (1 << random.bounded(8)));
                break;
            case 2:
                bytes[at] = char(0xff);
                break;
            default:
                bytes[at] = 0;
                break;
            }
        }
        auto result = readFinbook(bytes);
        if (!result) {
            QVERIFY(!result.error().message.isEmpty());
            continue;
        }
        ++loaded;
        // Whatever loads is a valid document: it saves and loads again.
        Document doc;
        adoptLoadedDocument(doc, std::move(*result));
        QVERIFY(readFinbook(serializeFinbook(doc)));
    }
    qInfo("fuzz: %d of 2000 mutated files loaded, the rest were refused", loaded);
}

QTEST_GUILESS_MAIN(TestFileMalformed)
#include "tst_file_malformed.moc"
