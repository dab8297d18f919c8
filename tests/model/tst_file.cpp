// The .finbook format: canonical round trips, sharing, safe saving, and a reader that turns
// every malformed file (truncated, foreign, out of range, absurd, fuzzed) into a typed error.
#include <finbook/model/finbook_file.h>

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest>

#include <cmath>
#include <limits>
#include <unistd.h>

using namespace finbook::model;

namespace {

float onGrid(int q)
{
    return float(q) / 65535.0f;
}

StrokeDataPtr makeStroke(int n, QRgb color, float width, float x0, float y0)
{
    auto data = std::make_shared<StrokeData>();
    data->color = color;
    data->width = width;
    for (int i = 0; i < n; ++i)
        data->points.push_back(
            {x0 + float(i) * 1.5f, y0 + std::sin(float(i)) * 3.0f, onGrid((i * 7919) % 65536)});
    return data;
}

DeformedStrokesPtr shiftedPose(const StrokeGroup &g, float dx)
{
    auto pose = std::make_shared<DeformedStrokes>();
    for (const Stroke &s : g.strokes) {
        auto points = s.data->points;
        for (StrokePoint &p : points)
            p.x += dx;
        pose->strokes.push_back(std::move(points));
    }
    return pose;
}

// Three frames: the second duplicates the first (shared stroke data and pose, new ids), the
// third has an empty object, a one-point stroke and an empty stroke.
void buildSample(Document &doc)
{
    std::vector<Frame> frames(3);
    Id next = 1;
    auto id = [&] { return next++; };
    Frame &a = frames[0];
    a.id = id();
    a.hold = 2;
    StrokeGroup body;
    body.id = id();
    body.name = QStringLiteral("body");
    body.strokes = {{id(), makeStroke(40, 0xff102030, 3.0f, 10, 10)},
                    {id(), makeStroke(25, 0x80ff0000, 5.5f, 50, 80)}};
    body.pins = {{id(), QPointF(10.25, 11), QPointF(12, 13.5)},
                 {id(), QPointF(60, 80), QPointF(61.125, 79)}};
    body.deformed = shiftedPose(body, 2.0f);
    StrokeGroup arm;
    arm.id = id();
    arm.name = QStringLiteral("Ärm ✋");
    arm.visible = false;
    arm.locked = true;
    arm.meshDensity = 2.5;
    arm.strokes = {{id(), makeStroke(12, 0xff00ff00, 1.0f, 200, 100)}};
    a.groups = {body, arm};

    Frame &b = frames[1];
    b.id = id();
    b.groups = a.groups;
    for (StrokeGroup &g : b.groups) {
        g.id = id();
        for (Stroke &s : g.strokes)
            s.id = id();
        for (Pin &p : g.pins)
            p.id = id();
    }

    Frame &c = frames[2];
    c.id = id();
    c.hold = 1000;
    StrokeGroup empty;
    empty.id = id();
    StrokeGroup odd;
    odd.id = id();
    odd.name = QStringLiteral("odd");
    odd.strokes = {{id(), makeStroke(1, 0xff000000, 7.0f, 5, 5)},
                   {id(), makeStroke(0, 0xff000000, 0.5f, 0, 0)}};
    c.groups = {empty, odd};

    DocumentSettings settings;
    settings.canvasSize = QSize(640, 360);
    settings.background = 0xfff0e0d0;
    settings.fps = 24;
    settings.loop = false;
    settings.playStart = 1;
    settings.playEnd = 2;
    doc.reset(std::move(frames), settings, next + 5);
}

void compareFrames(const std::vector<Frame> &actual, const std::vector<Frame> &expected)
{
    QCOMPARE(actual.size(), expected.size());
    for (std::size_t f = 0; f < actual.size(); ++f) {
        QCOMPARE(actual[f].id, expected[f].id);
        QCOMPARE(actual[f].hold, expected[f].hold);
        QCOMPARE(actual[f].groups.size(), expected[f].groups.size());
        for (std::size_t g = 0; g < actual[f].groups.size(); ++g) {
            const StrokeGroup &x = actual[f].groups[g], &y = expected[f].groups[g];
            QCOMPARE(x.id, y.id);
            QCOMPARE(x.name, y.name);
            QCOMPARE(x.visible, y.visible);
            QCOMPARE(x.locked, y.locked);
            QCOMPARE(x.meshDensity, y.meshDensity);
            QVERIFY(x.strokes == y.strokes);
            QVERIFY(x.pins == y.pins);
            QCOMPARE(bool(x.deformed), bool(y.deformed));
            if (x.deformed)
                QVERIFY(*x.deformed == *y.deformed);
        }
    }
}

QByteArray validBytes()
{
    Document doc;
    buildSample(doc);
    return serializeFinbook(doc);
}

// Offset of a section's payload, walking the section list as the format describes it.
qsizetype sectionPayload(const QByteArray &bytes, const char *name)
{
    qsizetype at = 12;
    while (at + 12 <= bytes.size()) {
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        if (bytes.mid(at, 4) == name)
            return at + 12;
        at += 12 + qsizetype(length);
    }
    return -1;
}

void putU32(QByteArray &bytes, qsizetype at, quint32 v)
{
    qToLittleEndian(v, bytes.data() + at);
}

FileErrorCode errorOf(const QByteArray &bytes, QString *message = nullptr)
{
    auto loaded = readFinbook(bytes);
    if (loaded)
        return FileErrorCode(-1);
    if (message)
        *message = loaded.error().message;
    return loaded.error().code;
}

QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestFile : public QObject {
    Q_OBJECT
private slots:
    void roundTripIsByteIdentical();
    void sharedStrokesStayShared();
    void offGridPressureIsQuantisedOnce();
    void pointsCostAboutTenBytes();
    void stalePoseIsDropped();
    void saveKeepsBackup();
    void openFailureLeavesDocumentUntouched();
    void saveFailureLeavesOldFile();
    void saveToReadOnlyFolderFails();
    void saveRefusesInvalidDocument();
    void everyPrefixIsAnError();
    void foreignFilesAreNotFinbook();
    void invalidValuesAreRejected_data();
    void invalidValuesAreRejected();
    void badNameUtf8IsRejected();
    void newerVersionIsRefused();
    void absurdCountsAreRefused();
    void unknownSectionsAreSkippedOrRefused();
    void bundledExampleIsCanonical();
    void fuzzedFilesNeverCrash();
};

void TestFile::roundTripIsByteIdentical()
{
    Document doc;
    buildSample(doc);
    const QByteArray first = serializeFinbook(doc);
    auto loaded = readFinbook(first);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->formatVersion, kFinbookFormatVersion);
    QCOMPARE(loaded->nextId, doc.nextId());
    QCOMPARE(loaded->settings, doc.settings());
    compareFrames(loaded->frames, doc.frames());

    Document reopened;
    reopened.reset(std::move(loaded->frames), loaded->settings, loaded->nextId);
    QCOMPARE(serializeFinbook(reopened), first);
}

void TestFile::sharedStrokesStayShared()
{
    Document doc;
    buildSample(doc);
    auto loaded = readFinbook(serializeFinbook(doc));
    QVERIFY(loaded);
    const auto &f = loaded->frames;
    for (std::size_t g = 0; g < 2; ++g) {
        for (std::size_t s = 0; s < f[0].groups[g].strokes.size(); ++s)
            QCOMPARE(f[1].groups[g].strokes[s].data.get(), f[0].groups[g].strokes[s].data.get());
    }
    QVERIFY(f[0].groups[0].strokes[0].data != f[0].groups[0].strokes[1].data);
    QCOMPARE(f[1].groups[0].deformed.get(), f[0].groups[0].deformed.get());

    // Unsharing the duplicate costs its points again on disk.
    std::vector<Frame> copies = doc.frames();
    for (StrokeGroup &g : copies[1].groups)
        for (Stroke &s : g.strokes)
            s.data = std::make_shared<StrokeData>(*s.data);
    Document unshared;
    unshared.reset(std::move(copies), doc.settings(), doc.nextId());
    const qsizetype saved = serializeFinbook(unshared).size() - serializeFinbook(doc).size();
    QCOMPARE(saved, qsizetype((40 + 25 + 12) * 10 + 3 * 12));
}

void TestFile::offGridPressureIsQuantisedOnce()
{
    Document doc;
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    auto data = std::make_shared<StrokeData>(*frames[0].groups[0].strokes[0].data);
    auto &points = data->points;
    points[0].pressure = 0.3f;
    points[1].pressure = 1.7f;
    points[2].pressure = -0.2f;
    frames[0].groups[0].strokes[0].data = data;
    frames[0].groups[0].deformed.reset();
    doc.reset(std::move(frames), doc.settings(), doc.nextId());

    const QByteArray first = serializeFinbook(doc);
    auto loaded = readFinbook(first);
    QVERIFY(loaded);
    const auto &p = loaded->frames[0].groups[0].strokes[0].data->points;
    QVERIFY(std::abs(p[0].pressure - 0.3f) <= 0.5f / 65535.0f + 1e-7f);
    QCOMPARE(p[1].pressure, 1.0f);
    QCOMPARE(p[2].pressure, 0.0f);
    Document reopened;
    reopened.reset(std::move(loaded->frames), loaded->settings, loaded->nextId);
    QCOMPARE(serializeFinbook(reopened), first);
}

void TestFile::pointsCostAboutTenBytes()
{
    std::vector<Frame> frames(1);
    frames[0].id = 1;
    frames[0].groups.resize(1);
    frames[0].groups[0].id = 2;
    for (Id s = 3; s < 23; ++s)
        frames[0].groups[0].strokes.push_back({s, makeStroke(500, 0xff000000, 2, 0, 0)});
    Document doc;
    doc.reset(std::move(frames), {}, 100);
    const double perPoint = double(serializeFinbook(doc).size()) / double(doc.pointCount());
    QVERIFY2(perPoint <= 10.1, qPrintable(QString::number(perPoint)));
}

void TestFile::stalePoseIsDropped()
{
    Document doc;
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    auto pose = std::make_shared<DeformedStrokes>(*frames[0].groups[0].deformed);
    pose->strokes.pop_back();
    frames[0].groups[0].deformed = pose;
    doc.reset(std::move(frames), doc.settings(), doc.nextId());
    auto loaded = readFinbook(serializeFinbook(doc));
    QVERIFY(loaded);
    QVERIFY(!loaded->frames[0].groups[0].deformed);
    QVERIFY(loaded->frames[1].groups[0].deformed);
}

void TestFile::saveKeepsBackup()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    QVERIFY(!QFile::exists(finbookBackupPath(path)));
    const QByteArray first = fileBytes(path);
    QCOMPARE(first, serializeFinbook(doc));

    Document opened;
    QVERIFY(!openFinbook(opened, path));
    compareFrames(opened.frames(), doc.frames());
    QCOMPARE(opened.settings(), doc.settings());
    QCOMPARE(opened.nextId(), doc.nextId());

    opened.setFrameHold(opened.frameAt(0).id, 7);
    QVERIFY(!saveFinbook(opened, path));
    QCOMPARE(fileBytes(finbookBackupPath(path)), first);
    QCOMPARE(fileBytes(path), serializeFinbook(opened));
    QVERIFY(!saveFinbook(doc, path)); // an older backup is replaced
    QCOMPARE(fileBytes(finbookBackupPath(path)), serializeFinbook(opened));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);
}

void TestFile::openFailureLeavesDocumentUntouched()
{
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    const QByteArray before = serializeFinbook(doc);
    const QString bad = dir.filePath(QStringLiteral("bad.finbook"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(validBytes().left(100));
    f.close();
    auto error = openFinbook(doc, bad);
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::Truncated);
    QVERIFY(error->message.contains(QLatin1String("bad.finbook")));
    QCOMPARE(serializeFinbook(doc), before);

    error = openFinbook(doc, dir.filePath(QStringLiteral("missing.finbook")));
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::OpenFailed);
    error = openFinbook(doc, dir.path());
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::OpenFailed);
    QCOMPARE(serializeFinbook(doc), before);
}

void TestFile::saveFailureLeavesOldFile()
{
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    const QString notADir = dir.filePath(QStringLiteral("plain"));
    QFile plain(notADir);
    QVERIFY(plain.open(QIODevice::WriteOnly));
    plain.close();
    auto error = saveFinbook(doc, notADir + QStringLiteral("/a.finbook"));
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::WriteFailed);
    QVERIFY(error->message.contains(QLatin1String("a.finbook")));

    // A backup that cannot be made stops the save (works even as root, unlike chmod).
    const QString path = dir.filePath(QStringLiteral("kept.finbook"));
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("kept.finbook~/blocker")));
    doc.setFrameHold(doc.frameAt(0).id, 9);
    error = saveFinbook(doc, path);
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::WriteFailed);
    QCOMPARE(fileBytes(path), old);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2); // plain, kept: no temp left
}

void TestFile::saveToReadOnlyFolderFails()
{
    if (::geteuid() == 0)
        QSKIP("running as root: a read-only folder does not stop writes");
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    const QString locked = dir.filePath(QStringLiteral("locked"));
    QVERIFY(QDir().mkpath(locked));
    const QString lockedPath = locked + QStringLiteral("/a.finbook");
    QVERIFY(!saveFinbook(doc, lockedPath));
    QFile::setPermissions(locked, QFile::ReadOwner | QFile::ExeOwner);
    const auto error = saveFinbook(Document(), lockedPath);
    QFile::setPermissions(locked, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::WriteFailed);
    QCOMPARE(fileBytes(lockedPath), serializeFinbook(doc));
}

void TestFile::saveRefusesInvalidDocument()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    std::vector<Frame> frames = doc.frames();
    auto data = std::make_shared<StrokeData>(*frames[2].groups[1].strokes[0].data);
    data->points[0].y = std::numeric_limits<float>::quiet_NaN();
    frames[2].groups[1].strokes[0].data = data;
    doc.reset(std::move(frames), doc.settings(), doc.nextId());
    auto error = saveFinbook(doc, path);
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::WriteFailed);
    QVERIFY2(error->message.contains(QLatin1String("frame 3, object \"odd\", stroke 1: point 1")),
             qPrintable(error->message));
    QCOMPARE(fileBytes(path), old);
}

void TestFile::everyPrefixIsAnError()
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

void TestFile::foreignFilesAreNotFinbook()
{
    QRandomGenerator random(7);
    QByteArray noise(4096, '\0');
    for (char &c : noise)
        c = char(random.bounded(256));
    const QByteArray png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    for (const QByteArray &bytes : {noise, png, QByteArray("hello, world\n")})
        QCOMPARE(errorOf(bytes), FileErrorCode::NotFinbook);
}

void TestFile::invalidValuesAreRejected_data()
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

void TestFile::invalidValuesAreRejected()
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
        frames[0].groups[0].pins[1].target.setY(double(nan));
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
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
    QVERIFY2(message.contains(expected, Qt::CaseInsensitive), qPrintable(message));
}

void TestFile::badNameUtf8IsRejected()
{
    QByteArray bytes = validBytes();
    const qsizetype at = bytes.indexOf("odd");
    QVERIFY(at > 0);
    bytes[at + 1] = char(0xc3); // a lead byte followed by an ASCII byte
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
    QVERIFY2(
        message.contains(QLatin1String("frame 3, object 2: the object name is not valid UTF-8"),
                         Qt::CaseInsensitive),
        qPrintable(message));
}

void TestFile::newerVersionIsRefused()
{
    QByteArray bytes = validBytes();
    putU32(bytes, 8, kFinbookFormatVersion + 1);
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::NewerVersion);
    QVERIFY2(message.contains(QLatin1String("newer")) && message.contains(QLatin1String("update")),
             qPrintable(message));
    putU32(bytes, 8, 0);
    QCOMPARE(errorOf(bytes), FileErrorCode::BadValue);
}

void TestFile::absurdCountsAreRefused()
{
    const QByteArray valid = validBytes();
    const qsizetype strokes = sectionPayload(valid, "STRK");
    const qsizetype frames = sectionPayload(valid, "FRAM");
    QVERIFY(strokes > 0 && frames > 0);
    for (qsizetype at : {strokes, strokes + 12, sectionPayload(valid, "POSE"), frames,
                         frames + 20 /* object count of frame 1 */}) {
        QByteArray bytes = valid;
        putU32(bytes, at, 0xffffffffu);
        QString message;
        QCOMPARE(errorOf(bytes, &message), FileErrorCode::TooLarge);
        QVERIFY(message.contains(QLatin1String("4294967295")));
    }
    QByteArray bytes = valid;
    qToLittleEndian<quint64>(~quint64(0), bytes.data() + frames - 8);
    QCOMPARE(errorOf(bytes), FileErrorCode::Truncated);
    bytes = valid;
    putU32(bytes, frames + 4, 0x7fffffffu); // frame record length
    QCOMPARE(errorOf(bytes), FileErrorCode::Truncated);
}

void TestFile::unknownSectionsAreSkippedOrRefused()
{
    const QByteArray valid = validBytes();
    const qsizetype frames = sectionPayload(valid, "FRAM") - 12;
    auto withSection = [&](const char *tag) {
        QByteArray section(tag, 4);
        section += QByteArray("\x03\0\0\0\0\0\0\0abc", 11);
        return QByteArray(valid).insert(frames, section);
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

void TestFile::bundledExampleIsCanonical()
{
    const QString path = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
    if (!QFile::exists(path))
        QSKIP("resources/examples/walk.finbook is not there");
    Document doc;
    const auto error = openFinbook(doc, path);
    QVERIFY2(!error, error ? qPrintable(error->message) : "");
    QVERIFY(doc.frameCount() >= 12);
    QCOMPARE(serializeFinbook(doc), fileBytes(path));
}

void TestFile::fuzzedFilesNeverCrash()
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
        doc.reset(std::move(result->frames), result->settings, result->nextId);
        QVERIFY(readFinbook(serializeFinbook(doc)));
    }
    qInfo("fuzz: %d of 2000 mutated files loaded, the rest were refused", loaded);
}

QTEST_GUILESS_MAIN(TestFile)
#include "tst_file.moc"
