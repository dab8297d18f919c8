// The .finbook format: canonical round trips, shared strokes, and safe saving (atomic, with a
// backup, never over a good file with bad bytes).
#include "tst_file_sample.h"

#include <QDir>
#include <QTemporaryDir>

#include <limits>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

// Largest id stored anywhere in a document's frames.
static Id largestId(const std::vector<Layer> &layers)
{
    Id largest = 0;
    for (const Layer &l : layers)
        largest = std::max(largest, l.id);
    for (const Layer &l : layers)
        for (const Frame &f : l.cels) {
            largest = std::max(largest, f.id);
            for (const StrokeGroup &g : f.groups) {
                largest = std::max(largest, g.id);
                for (const Stroke &s : g.strokes)
                    largest = std::max(largest, s.id);
                for (const Pin &p : g.rig.pins)
                    largest = std::max(largest, p.id);
            }
        }
    return largest;
}

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
    void bundledExampleIsCanonical();
};

void TestFile::roundTripIsByteIdentical()
{
    Document doc;
    buildSample(doc);
    const QByteArray first = serializeFinbook(doc);
    auto loaded = readFinbook(first);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->formatVersion, kFinbookFormatVersion);
    // The stored next id is canonical (one past the largest id), not the allocation counter,
    // which depends on undo history.
    QCOMPARE(loaded->nextId, largestId(doc.layers()) + 1);
    QCOMPARE(loaded->settings, doc.settings());
    compareFrames(loaded->frames, doc.frames());

    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
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
    adoptLoadedDocument(reopened, std::move(*loaded));
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
    QCOMPARE(opened.nextId(), largestId(doc.layers()) + 1);

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

QTEST_GUILESS_MAIN(TestFile)
#include "tst_file.moc"
