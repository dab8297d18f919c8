// `finbook thumbnail`: the first frame read without the rest of the file gives exactly the
// picture a full open gives, reads a small part of a large file, and every damaged or hostile
// file ends in exit code 2 with no PNG written.
#include "../../model/src/io/crc32c.h"
#include "thumbnail/first_frame.h"
#include "thumbnail/thumbnail_command.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>
#include <finbook/model/sound/sound_clip.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTextStream>
#include <QtEndian>
#include <QtTest>

#include <cmath>
#include <limits>
#include <sys/stat.h>

using namespace finbook;

namespace {

const QString kExample = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
// readFirstFrame's last argument for testing its own walk over the file, without the whole check.
constexpr qint64 kNoWholeCheck = -1;

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QString writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(bytes);
    return path;
}

QImage render(const model::LoadedDocument &doc)
{
    return model::renderFrame(doc.frames.front(), doc.settings, QSize(256, 144));
}

// `frames` frames of `strokes` strokes of `points` points each, every frame its own drawing
// (so the stroke table holds frames × strokes entries), the first frame's object posed.
QByteArray manyFrames(int frames, int strokes, int points)
{
    std::vector<model::Frame> list;
    model::Id id = 1;
    for (int f = 0; f < frames; ++f) {
        model::Frame frame;
        frame.id = id++;
        model::StrokeGroup group;
        group.id = id++;
        group.name = QStringLiteral("object %1").arg(f);
        for (int s = 0; s < strokes; ++s) {
            auto data = std::make_shared<model::StrokeData>();
            data->color = qRgb(20 * s % 255, 40, 200);
            data->width = 2.0f + float(s % 4);
            data->points.reserve(std::size_t(points));
            // A pen line as people draw it: samples about 1.5 px apart on a widening spiral,
            // with the pressure rising and falling smoothly.
            const double cx = 100 + (s * 97 + f * 11) % 1080, cy = 80 + (s * 53 + f * 7) % 560;
            double angle = 0;
            for (int p = 0; p < points; ++p) {
                const double r = 10 + 0.06 * p;
                angle += 1.5 / r;
                data->points.push_back({float(cx + r * std::cos(angle)),
                                        float(cy + r * std::sin(angle)),
                                        float(0.5 + 0.4 * std::sin(p / 40.0))});
            }
            group.strokes.push_back({id++, data});
        }
        frame.groups.push_back(std::move(group));
        list.push_back(std::move(frame));
    }
    return model::serializeFinbook(list, model::DocumentSettings{});
}

// Three frames of one object each (ids 1 to 9), a sound clip with id `clipId` and, when
// `nanInLastFrame`, a point that is not a number in the last frame's stroke.
QByteArray threeFramesWithSound(model::Id clipId, bool nanInLastFrame = false)
{
    std::vector<model::Frame> frames;
    model::Id id = 1;
    for (int f = 0; f < 3; ++f) {
        model::Frame frame;
        frame.id = id++;
        model::StrokeGroup group;
        group.id = id++;
        group.name = QStringLiteral("object");
        auto data = std::make_shared<model::StrokeData>();
        data->points = {{10.0f + f, 10.0f, 1.0f}, {90.0f, 60.0f + f, 1.0f}};
        if (nanInLastFrame && f == 2)
            data->points[1].x = std::numeric_limits<float>::quiet_NaN();
        group.strokes.push_back({id++, data});
        frame.groups.push_back(std::move(group));
        frames.push_back(std::move(frame));
    }
    model::SoundClip clip;
    clip.id = clipId;
    clip.name = QStringLiteral("click.wav");
    clip.bytes = QByteArray(300, 'x'); // not decoded when read
    return model::serializeFinbook(frames, model::DocumentSettings{}, {}, {clip});
}

// `bytes` with the document's next free id set to `next`, its checksum made to match
// (layout in model/src/finbook_file_format.h: the document section comes first).
QByteArray withNextId(QByteArray bytes, quint64 next)
{
    const qsizetype section = 12, payload = section + 12;
    const auto length = qsizetype(qFromLittleEndian<quint64>(bytes.constData() + section + 4));
    qToLittleEndian<quint64>(next, bytes.data() + payload + 25);
    qToLittleEndian<quint32>(
        model::io::crc32c(0, bytes.constData() + section, std::size_t(12 + length)),
        bytes.data() + payload + length);
    return bytes;
}

QStringList seedFiles()
{
    QStringList files;
    const QDir seeds(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/fuzz/seeds"));
    for (const QString &name : seeds.entryList({QStringLiteral("*.finbook")}, QDir::Files))
        files << seeds.filePath(name);
    return files << kExample;
}

int thumbnail(const QStringList &arguments, QString *error = nullptr)
{
    QString text;
    QTextStream err(&text);
    const int code = app::runThumbnailCommand(arguments, err);
    err.flush();
    if (error)
        *error = text;
    return code;
}

} // namespace

class TestThumbnail : public QObject {
    Q_OBJECT
private slots:
    void firstFrameIsWhatOpeningGives_data();
    void firstFrameIsWhatOpeningGives();
    void readsOnlyTheFirstFrame();
    void everyDamagedByteIsRefused();
    void cutOffFilesAreRefused_data();
    void cutOffFilesAreRefused();
    void hostileFilesAreRefused_data();
    void hostileFilesAreRefused();
    void randomDamageNeverCrashes();
    void refusesWhatOpeningRefuses_data();
    void refusesWhatOpeningRefuses();
    void commandWritesAPngOfTheSize();
    void badArgumentsAndOutputs();
    void realProcess();
    void writeBigDocument();
};

void TestThumbnail::firstFrameIsWhatOpeningGives_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<qint64>("whole");
    for (const QString &path : seedFiles()) {
        const QByteArray name = QFileInfo(path).fileName().toUtf8();
        QTest::newRow(name + " whole sections") << path << app::kWholeSectionBytes;
        QTest::newRow(name + " first frame only") << path << qint64(0);
    }
}

void TestThumbnail::firstFrameIsWhatOpeningGives()
{
    QFETCH(QString, path);
    QFETCH(qint64, whole);
    auto full = model::loadFinbook(path);
    if (!full)
        QSKIP("not a file that opens (a recovery seed)");
    qint64 read = 0;
    auto first = app::readFirstFrame(path, whole, &read);
    QVERIFY2(first, first ? "" : qPrintable(first.error().message));
    QCOMPARE(first->frames.size(), std::size_t(1));
    QCOMPARE(first->settings, full->settings);
    QCOMPARE(first->formatVersion, full->formatVersion);
    const model::Frame &a = first->frames.front(), &b = full->frames.front();
    QCOMPARE(a.id, b.id);
    QCOMPARE(a.groups.size(), b.groups.size());
    for (std::size_t g = 0; g < a.groups.size(); ++g) {
        QCOMPARE(a.groups[g].strokes, b.groups[g].strokes);
        QCOMPARE(a.groups[g].rig, b.groups[g].rig);
        QCOMPARE(a.groups[g].isDeformed(), b.groups[g].isDeformed());
        if (a.groups[g].isDeformed())
            QCOMPARE(*a.groups[g].deformed, *b.groups[g].deformed);
    }
    QCOMPARE(render(*first), render(*full));
    QVERIFY(read <= QFileInfo(path).size());
}

void TestThumbnail::readsOnlyTheFirstFrame()
{
    QTemporaryDir dir;
    const int frames = 100, strokes = 20, points = 500; // 1M points, 10 MB
    const QString path = writeFile(dir.filePath(QStringLiteral("many.finbook")),
                                   manyFrames(frames, strokes, points));
    const qint64 size = QFileInfo(path).size();
    qint64 read = 0;
    auto first = app::readFirstFrame(path, app::kWholeSectionBytes, &read, kNoWholeCheck);
    QVERIFY2(first, first ? "" : qPrintable(first.error().message));
    // The first frame's points, the frame list (small: read whole for its checksum) and a few
    // headers: about a hundredth of the file.
    const qint64 firstFramePoints = qint64(strokes) * points * 10;
    const qint64 frameList = qint64(frames) * (4 + 16 + 4 + 4 + 29 + 13 + strokes * 12);
    QVERIFY2(read < firstFramePoints + frameList + 4096, qPrintable(QString::number(read)));
    QVERIFY(read < size / 50);
    auto full = model::loadFinbook(path);
    QVERIFY(full);
    QCOMPARE(render(*first), render(*full));
}

// The example is smaller than kWholeSectionBytes: every section's checksum is checked, so a
// changed byte anywhere is found.
void TestThumbnail::everyDamagedByteIsRefused()
{
    const QByteArray bytes = readAll(kExample);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("damaged.finbook"));
    int refused = 0;
    for (qsizetype at = 0; at < bytes.size(); at += 61) {
        QByteArray damaged = bytes;
        damaged[at] = char(damaged[at] ^ 0x10);
        writeFile(path, damaged);
        auto first = app::readFirstFrame(path, app::kWholeSectionBytes, nullptr, kNoWholeCheck);
        if (first)
            QFAIL(qPrintable(QStringLiteral("a changed byte at %1 went unnoticed").arg(at)));
        ++refused;
    }
    QVERIFY(refused > 2000);
}

void TestThumbnail::cutOffFilesAreRefused_data()
{
    QTest::addColumn<qint64>("whole");
    QTest::addColumn<qint64>("wholeCheck");
    QTest::newRow("whole sections") << app::kWholeSectionBytes << kNoWholeCheck;
    QTest::newRow("first frame only") << qint64(0) << kNoWholeCheck;
    QTest::newRow("file checked whole") << qint64(0) << app::kWholeCheckBytes;
}

// The section lengths must add up to the file's size, so a file cut anywhere is refused even
// where the cut is past the first frame.
void TestThumbnail::cutOffFilesAreRefused()
{
    QFETCH(qint64, whole);
    QFETCH(qint64, wholeCheck);
    const QByteArray bytes = readAll(kExample);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("cut.finbook"));
    for (qsizetype size = 0; size < bytes.size(); size += std::max<qsizetype>(1, size / 7)) {
        writeFile(path, bytes.left(size));
        QVERIFY2(!app::readFirstFrame(path, whole, nullptr, wholeCheck),
                 qPrintable(QString::number(size)));
    }
    writeFile(path, bytes + QByteArray(1, '\0'));
    QVERIFY(!app::readFirstFrame(path, whole, nullptr, wholeCheck));
}

void TestThumbnail::hostileFilesAreRefused_data()
{
    QTest::addColumn<QByteArray>("bytes");
    const QByteArray example = readAll(kExample);
    const auto patched = [](QByteArray bytes, qsizetype at, quint32 value) {
        qToLittleEndian<quint32>(value, bytes.data() + at);
        return bytes;
    };
    // A one-stroke document to patch: its layout is fixed (finbook_file_format.h).
    const QByteArray small = manyFrames(1, 1, 3);
    const qsizetype strokeCount = 12 + 12 + 29 + 4 + 12; // header, DOCU, its crc, STRK header
    QTest::newRow("empty") << QByteArray();
    QTest::newRow("not a finbook") << QByteArray("GIF89a this is not an animation at all");
    QTest::newRow("newer version") << patched(example, 8, 99);
    QTest::newRow("only the header") << example.left(12);
    QTest::newRow("stroke table claims 4e9 entries") << patched(small, strokeCount, 0xfffffff0u);
    QTest::newRow("points claim 4e9") << patched(small, strokeCount + 4 + 8, 0xfffffff0u);
    QTest::newRow("section length 2^60") << [&] {
        QByteArray b = small;
        qToLittleEndian<quint64>(quint64(1) << 60, b.data() + 12 + 4);
        return b;
    }();
    QTest::newRow("random bytes after the magic") << example.left(8) + QByteArray(4000, '\xa5');
}

// Reading the first frame only, no checksum covers these patches: the structure checks alone
// must refuse them.
void TestThumbnail::hostileFilesAreRefused()
{
    QFETCH(QByteArray, bytes);
    QTemporaryDir dir;
    const QString in = writeFile(dir.filePath(QStringLiteral("in.finbook")), bytes);
    const QString out = dir.filePath(QStringLiteral("out.png"));
    for (qint64 whole : {app::kWholeSectionBytes, qint64(0)}) {
        QVERIFY(!app::readFirstFrame(in, whole, nullptr, kNoWholeCheck));
    }
    QVERIFY(!app::readFirstFrame(in));
    QString error;
    QCOMPARE(thumbnail({in, out, QStringLiteral("128")}, &error), 2);
    QVERIFY(!QFileInfo::exists(out));
    QCOMPARE(error.count(QLatin1Char('\n')), 1);
}

// Mutations of every seed, read in both modes: a refusal or one frame, never a crash (the
// sanitizer build runs this too).
void TestThumbnail::randomDamageNeverCrashes()
{
    QRandomGenerator random(23);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mutant.finbook"));
    int opened = 0, refused = 0;
    for (const QString &seed : seedFiles()) {
        const QByteArray bytes = readAll(seed);
        for (int round = 0; round < 150; ++round) {
            QByteArray mutant = bytes;
            const int changes = 1 + int(random.bounded(4));
            for (int c = 0; c < changes; ++c) {
                const qsizetype at = qsizetype(random.bounded(quint32(mutant.size())));
                mutant[at] = char(random.bounded(256));
            }
            writeFile(path, mutant);
            auto first = app::readFirstFrame(path, round % 2 ? app::kWholeSectionBytes : 0, nullptr,
                                             round % 3 ? kNoWholeCheck : app::kWholeCheckBytes);
            if (first) {
                QCOMPARE(first->frames.size(), std::size_t(1));
                ++opened;
            } else {
                ++refused;
            }
        }
    }
    QVERIFY(refused > 0);
    qInfo("%d mutants refused, %d read", refused, opened);
}

void TestThumbnail::refusesWhatOpeningRefuses_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("sound clip id at the next free id") << withNextId(threeFramesWithSound(50), 50);
    QTest::newRow("sound clip id shared with a stroke") << threeFramesWithSound(3);
    QTest::newRow("last frame's point not a number") << threeFramesWithSound(50, true);
}

// `finbook info` and opening refuse these for what lies past the first frame; the thumbnailer
// refuses them too, with the same reason (issue: it used to draw them).
void TestThumbnail::refusesWhatOpeningRefuses()
{
    QFETCH(QByteArray, bytes);
    QTemporaryDir dir;
    const QString in = writeFile(dir.filePath(QStringLiteral("in.finbook")), bytes);
    QVERIFY(model::loadFinbook(
        writeFile(dir.filePath(QStringLiteral("sound.finbook")), threeFramesWithSound(50))));
    auto opened = model::loadFinbook(in);
    QVERIFY(!opened);
    auto first = app::readFirstFrame(in);
    QVERIFY(!first);
    // The reason opening gives ("Cannot open "in.finbook". <reason>") ends the thumbnailer's.
    const QString reason = opened.error().message.section(QStringLiteral("\". "), 1);
    QVERIFY2(!reason.isEmpty() && first.error().message.endsWith(reason),
             qPrintable(first.error().message + QStringLiteral(" | ") + opened.error().message));
    // Its own walk, which reads only the first frame, would have drawn it.
    QVERIFY(app::readFirstFrame(in, app::kWholeSectionBytes, nullptr, kNoWholeCheck));
    const QString out = dir.filePath(QStringLiteral("out.png"));
    QString error;
    QCOMPARE(thumbnail({in, out, QStringLiteral("128")}, &error), 2);
    QVERIFY(!QFileInfo::exists(out));
    QCOMPARE(error.count(QLatin1Char('\n')), 1);
}

void TestThumbnail::commandWritesAPngOfTheSize()
{
    QTemporaryDir dir;
    for (int size : {1, 16, 128, 256, 1024}) {
        const QString out = dir.filePath(QStringLiteral("t%1.png").arg(size));
        QString error;
        QCOMPARE(thumbnail({kExample, out, QString::number(size)}, &error), 0);
        QVERIFY(error.isEmpty());
        const QImage png(out);
        QVERIFY(!png.isNull());
        QCOMPARE(std::max(png.width(), png.height()), size);
        auto full = model::loadFinbook(kExample);
        const QSize canvas = full->settings.canvasSize;
        if (size >= 128) { // the canvas's aspect, to the pixel
            QVERIFY(qAbs(png.width() * canvas.height() - png.height() * canvas.width()) <=
                    std::max(canvas.width(), canvas.height()));
            const QImage expected =
                model::renderFrame(full->frames.front(), full->settings, png.size());
            QCOMPARE(png.convertToFormat(QImage::Format_ARGB32),
                     expected.convertToFormat(QImage::Format_ARGB32));
        }
    }
}

void TestThumbnail::badArgumentsAndOutputs()
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("out.png"));
    QCOMPARE(thumbnail({kExample, out}), 2);
    QCOMPARE(thumbnail({kExample, out, QStringLiteral("128"), QStringLiteral("x")}), 2);
    for (const char *size : {"0", "-5", "abc", "2049", "1e3", ""})
        QCOMPARE(thumbnail({kExample, out, QString::fromLatin1(size)}), 2);
    QVERIFY(!QFileInfo::exists(out));
    QCOMPARE(thumbnail({dir.path(), out, QStringLiteral("128")}), 2); // a folder
    QCOMPARE(
        thumbnail({dir.filePath(QStringLiteral("missing.finbook")), out, QStringLiteral("128")}),
        2);
    const QString fifo = dir.filePath(QStringLiteral("pipe.finbook"));
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QCOMPARE(thumbnail({fifo, out, QStringLiteral("128")}), 2); // refused unread, no wait
    QVERIFY(!QFileInfo::exists(out));
    // The output cannot be written: exit 1, nothing left behind.
    const QString noFolder = dir.filePath(QStringLiteral("no/such/folder/out.png"));
    QCOMPARE(thumbnail({kExample, noFolder, QStringLiteral("128")}), 1);
    QVERIFY(!QFileInfo::exists(noFolder));
}

void TestThumbnail::realProcess()
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("walk.png"));
    QProcess process;
    QElapsedTimer timer;
    timer.start();
    process.start(QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook"),
                  {QStringLiteral("thumbnail"), kExample, out, QStringLiteral("256")});
    QVERIFY(process.waitForFinished(60000));
    qInfo("finbook thumbnail on the example: %lld ms (not checked)",
          static_cast<long long>(timer.elapsed()));
    QCOMPARE(process.exitCode(), 0);
    QVERIFY(process.readAllStandardError().isEmpty());
    QCOMPARE(QImage(out).width(), 256);

    const QString damaged =
        writeFile(dir.filePath(QStringLiteral("damaged.finbook")), readAll(kExample).left(5000));
    const QString none = dir.filePath(QStringLiteral("none.png"));
    process.start(QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook"),
                  {QStringLiteral("thumbnail"), damaged, none, QStringLiteral("256")});
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitCode(), 2);
    QCOMPARE(process.readAllStandardError().count('\n'), 1);
    QVERIFY(!QFileInfo::exists(none));
}

// FINBOOK_WRITE_BIG_DOCUMENT=PATH writes a 10M-point animation (250 frames × 40 strokes ×
// 1,000 points, about 100 MB) there, to time the thumbnailer on (README); skipped otherwise.
void TestThumbnail::writeBigDocument()
{
    const QString path = qEnvironmentVariable("FINBOOK_WRITE_BIG_DOCUMENT");
    if (path.isEmpty())
        QSKIP("set FINBOOK_WRITE_BIG_DOCUMENT=PATH to write the 10M-point document");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.write(manyFrames(250, 40, 1000)) > 0);
}

QTEST_MAIN(TestThumbnail)
#include "tst_thumbnail.moc"
