// The loader against the files of issue 14: ids at 2^64 - 1, names full of terminal escapes,
// pipes and devices, wrong files checked by their header first, tables of millions of empty
// entries, and a machine out of memory. Each case is refused with one clear sentence (or, for
// memory, said as such: app/tst_limits), never a hang, a wrapped id or a filled memory.
#include "file_builder.h"
#include "tst_file_sample.h"

#include <finbook/model/io/printable_text.h>

#include <QElapsedTimer>
#include <QTemporaryDir>

#include <sys/stat.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;
namespace fb = file_build;

namespace {
// One frame with one object named `name` whose only stroke refers to stroke data that does
// not exist, so the error names the object.
QByteArray badObjectNamed(const QByteArray &name)
{
    return fb::fileV1(fb::document(), fb::emptyTable(), fb::emptyTable(),
                      fb::frameList({fb::frame(1, {fb::object(2, {{3, 7}}, name)})}));
}

// Peak resident memory of this process since the last reset (Linux: VmHWM).
qint64 peakKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').first().toLongLong();
    return -1;
}
bool resetPeak()
{
    QFile refs(QStringLiteral("/proc/self/clear_refs"));
    return refs.open(QIODevice::WriteOnly) && refs.write("5") == 1;
}
} // namespace

class TestLoaderHardening : public QObject {
    Q_OBJECT
private slots:
    void hugeNextIdIsRefused();
    void hugeIdsAreRefused();
    void controlCharactersInNamesAreEscaped();
    void printableTextKeepsLettersAndEscapesControls();
    void pipesAndDevicesAreRefusedUnread();
    void headerIsCheckedBeforeTheRest();
    void emptyPoseTableBombIsRefused();
    void emptyEntryBombsAreRefused_data();
    void emptyEntryBombsAreRefused();
    void realDocumentsFitTheBudget();
};

void TestLoaderHardening::hugeNextIdIsRefused()
{
    // 2^64 - 1 was accepted: new ids wrapped to 0 and the document could never be saved again.
    for (const quint64 next : {~quint64(0), quint64(kMaxId) + 2}) {
        const QByteArray bytes =
            fb::fileV1(fb::document(640, 360, next), fb::emptyTable(), fb::emptyTable(),
                       fb::frameList({fb::frame(1, {fb::object(2, {})})}));
        QString message;
        QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
        QVERIFY2(message.contains(QLatin1String("next free id")), qPrintable(message));
    }
    // The largest id that may be stored still opens, and its next id is 2^63.
    const QByteArray edge =
        fb::fileV1(fb::document(640, 360, kMaxId + 1), fb::emptyTable(), fb::emptyTable(),
                   fb::frameList({fb::frame(kMaxId, {fb::object(2, {})})}));
    auto loaded = readFinbook(edge);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->nextId, kMaxId + 1);
}

void TestLoaderHardening::hugeIdsAreRefused()
{
    for (const quint64 id : {quint64(kMaxId) + 1, ~quint64(0)}) {
        const QByteArray bytes =
            fb::fileV1(fb::document(640, 360, 1000), fb::emptyTable(), fb::emptyTable(),
                       fb::frameList({fb::frame(1, {fb::object(id, {})})}));
        QString message;
        QCOMPARE(errorOf(bytes, &message), FileErrorCode::BadValue);
        QVERIFY2(message.contains(QLatin1String("larger than any id")), qPrintable(message));
    }
}

void TestLoaderHardening::controlCharactersInNamesAreEscaped()
{
    const QByteArray name("\x1b[31mred\x1b]0;pwned\x07\r\n\xe2\x80\xae"
                          "evil\x7f");
    QString message;
    QCOMPARE(errorOf(badObjectNamed(name), &message), FileErrorCode::BadValue);
    for (QChar c : message)
        QVERIFY2(c.unicode() >= 0x20 && c.unicode() != 0x7f && c.unicode() != 0x202e,
                 qPrintable(QStringLiteral("U+%1 in %2").arg(c.unicode(), 4, 16).arg(message)));
    QVERIFY2(message.contains(QLatin1String("\\x1b[31mred\\x1b]0;pwned\\x07\\x0d\\x0a"
                                            "\\u{202e}evil\\x7f")),
             qPrintable(message));
}

void TestLoaderHardening::printableTextKeepsLettersAndEscapesControls()
{
    QCOMPARE(printableText(QStringLiteral("Ärm ✋ 腕")), QStringLiteral("Ärm ✋ 腕"));
    QCOMPARE(printableText(QStringLiteral("a\tb")), QStringLiteral("a\\x09b"));
    QCOMPARE(printableText(QString(QChar(0x9b))), QStringLiteral("\\x9b")); // C1 CSI
    QCOMPARE(printableText(QStringLiteral("C:\\x")), QStringLiteral("C:\\\\x"));
    QCOMPARE(printableText(QStringLiteral("C:\\dir")), QStringLiteral("C:\\dir"));
}

void TestLoaderHardening::pipesAndDevicesAreRefusedUnread()
{
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("pipe.finbook"));
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QElapsedTimer clock;
    clock.start();
    // Nobody writes to the pipe: reading it would wait for ever.
    auto loaded = loadFinbook(fifo);
    QVERIFY(!loaded);
    QCOMPARE(loaded.error().code, FileErrorCode::OpenFailed);
    QVERIFY2(loaded.error().message.contains(QLatin1String("pipe")),
             qPrintable(loaded.error().message));
    for (const char *device : {"/dev/zero", "/dev/null", "/dev/urandom"}) {
        if (!QFile::exists(QLatin1String(device)))
            continue;
        auto refused = loadFinbook(QLatin1String(device));
        QVERIFY(!refused);
        QCOMPARE(refused.error().code, FileErrorCode::OpenFailed);
    }
    QVERIFY(clock.elapsed() < 60000);
}

void TestLoaderHardening::headerIsCheckedBeforeTheRest()
{
    // 1 GiB that is not a .finbook, and 1 GiB announcing a newer format: both refused after
    // the header, without reading (or allocating) the rest. Sparse files cost no disk.
    QTemporaryDir dir;
    for (const QByteArray &head : {QByteArray(12, '\0'), QByteArray("\x89"
                                                                    "FBK\r\n\x1a\n\x09\0\0\0",
                                                                    12)}) {
        const QString path = dir.filePath(QStringLiteral("big.finbook"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(head);
        QVERIFY(f.resize(qint64(1) << 30));
        f.close();
        QVERIFY(resetPeak());
        const qint64 before = peakKiB();
        auto loaded = loadFinbook(path);
        const qint64 grew = peakKiB() - before;
        QVERIFY(!loaded);
        QVERIFY(loaded.error().code == FileErrorCode::NotFinbook ||
                loaded.error().code == FileErrorCode::Damaged); // version 9: damage
        QVERIFY2(grew < 64 * 1024, qPrintable(QStringLiteral("%1 KiB").arg(grew)));
    }
}

void TestLoaderHardening::emptyPoseTableBombIsRefused()
{
    // The pose table of N empty poses: 4 bytes each in the file, ~100 in memory.
    const quint32 poses = 8u << 20; // 32 MiB of file
    fb::Bytes table;
    table.u32(poses).raw(QByteArray(qsizetype(poses) * 4, '\0'));
    const QByteArray bytes = fb::fileV1(fb::document(), fb::emptyTable(), table,
                                        fb::frameList({fb::frame(1, {fb::object(2, {})})}));
    QVERIFY(resetPeak());
    const qint64 before = peakKiB();
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::TooLarge);
    const qint64 grewMiB = (peakKiB() - before) / 1024;
    qInfo("pose bomb of %lld MiB: refused, peak grew %lld MiB", bytes.size() >> 20, grewMiB);
    QVERIFY2(message.contains(QLatin1String("memory")), qPrintable(message));
    QVERIFY(grewMiB <= kLoadMemoryFactor * (bytes.size() >> 20) + (kLoadMemorySlack >> 20));
}

void TestLoaderHardening::emptyEntryBombsAreRefused_data()
{
    QTest::addColumn<QByteArray>("bytes");
    const int n = 3 << 20;
    // Millions of empty stroke-data entries nobody uses (12 bytes each).
    fb::Bytes strokes;
    strokes.u32(quint32(n));
    for (int i = 0; i < n; ++i)
        strokes.u32(0xff000000u).f32(1.0f).u32(0);
    QTest::newRow("empty stroke data")
        << fb::fileV1(fb::document(), strokes, fb::emptyTable(),
                      fb::frameList({fb::frame(1, {fb::object(2, {})})}));
    // Millions of empty objects in one frame (30 bytes each, a few hundred in memory).
    fb::Bytes frame;
    frame.u64(1).u32(1).u32(quint32(n / 2));
    for (int i = 0; i < n / 2; ++i)
        frame.record(fb::object(quint64(i) + 2, {}, QByteArray()));
    fb::Bytes frames;
    frames.u32(1).record(frame);
    QTest::newRow("empty objects") << fb::fileV1(fb::document(640, 360, quint64(n) + 10),
                                                 fb::emptyTable(), fb::emptyTable(), frames);
}

void TestLoaderHardening::emptyEntryBombsAreRefused()
{
    QFETCH(QByteArray, bytes);
    QString message;
    QCOMPARE(errorOf(bytes, &message), FileErrorCode::TooLarge);
    QVERIFY2(message.contains(QLatin1String("memory")), qPrintable(message));
}

void TestLoaderHardening::realDocumentsFitTheBudget()
{
    // A plain drawing of 3 million points (30 MB) loads: the budget only refuses files that
    // describe more than their bytes can hold.
    Document doc;
    std::vector<Frame> frames(30);
    Id next = 1;
    for (Frame &f : frames) {
        f.id = next++;
        StrokeGroup g;
        g.id = next++;
        for (int s = 0; s < 100; ++s) {
            auto data = std::make_shared<StrokeData>();
            for (int i = 0; i < 1000; ++i)
                data->points.push_back({float(i), float(s), 1.0f});
            g.strokes.push_back({next++, data});
        }
        f.groups.push_back(std::move(g));
    }
    doc.reset(std::move(frames), DocumentSettings(), next);
    const QByteArray bytes = serializeFinbook(doc);
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->frames.size(), std::size_t(30));
}

QTEST_GUILESS_MAIN(TestLoaderHardening)
#include "tst_loader_hardening.moc"
