// readPictureLayers: plain pictures and OpenRaster stacks become positioned layers; damaged,
// oversized and hostile files get a sentence and cost bounded memory.
#include <finbook/model/picture/picture_import.h>

#include <QBuffer>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <quazip/quazip.h>
#include <quazip/quazipfile.h>

#include <cstring>
#include <functional>
#include <map>

using namespace finbook;
using namespace finbook::model;

namespace {

QByteArray encoded(const QImage &image, const char *format, int quality = -1)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, format, quality))
        qFatal("cannot encode a test picture as %s", format);
    return bytes;
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// A picture with colour and alpha that vary from pixel to pixel (premultiplied-exact: every
// alpha is 0 or 255 or its colours are multiples that survive premultiplication).
QImage patterned(int w, int h, QRgb tint)
{
    QImage image(w, h, QImage::Format_ARGB32);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.setPixel(x, y,
                           (x + y) % 5 == 0
                               ? qRgba(0, 0, 0, 0)
                               : qRgba((qRed(tint) + 3 * x) % 256, (qGreen(tint) + 5 * y) % 256,
                                       qBlue(tint), 255));
    return image;
}

// A GIF of at most four colours (index 3 transparent) written by hand, independently of any
// reader under test: LZW with a clear code before every two pixels keeps the codes 3 bits wide.
QByteArray handMadeGif(int w, int h, const std::function<int(int, int)> &index,
                       const QRgb palette[3])
{
    QByteArray gif("GIF89a");
    const auto word = [&gif](int v) {
        gif += char(v & 0xff);
        gif += char((v >> 8) & 0xff);
    };
    word(w);
    word(h);
    gif += char(0xf1); // global colour table of 4 entries
    gif += char(0);
    gif += char(0);
    for (int i = 0; i < 4; ++i) {
        const QRgb c = i < 3 ? palette[i] : qRgb(0, 0, 0);
        gif += char(qRed(c));
        gif += char(qGreen(c));
        gif += char(qBlue(c));
    }
    gif += QByteArray("\x21\xf9\x04\x01\x00\x00\x03\x00", 8); // colour 3 is transparent
    gif += char(0x2c);
    word(0);
    word(0);
    word(w);
    word(h);
    gif += char(0);
    gif += char(2); // LZW minimum code size
    QByteArray data;
    quint32 bits = 0;
    int count = 0;
    const auto code = [&](int c) {
        bits |= quint32(c) << count;
        count += 3;
        while (count >= 8) {
            data += char(bits & 0xff);
            bits >>= 8;
            count -= 8;
        }
    };
    for (int i = 0; i < w * h; ++i) {
        if (i % 2 == 0)
            code(4); // clear
        code(index(i % w, i / w));
    }
    code(5); // end of information
    if (count > 0)
        data += char(bits & 0xff);
    for (qsizetype at = 0; at < data.size(); at += 255) {
        const QByteArray block = data.mid(at, 255);
        gif += char(block.size());
        gif += block;
    }
    gif += char(0);
    gif += char(0x3b);
    return gif;
}

using Entries = std::vector<std::pair<QString, QByteArray>>;

// An OpenRaster file as Krita writes it: "mimetype" first and stored, then the rest deflated.
// `write` (optional) streams one more entry's bytes itself (for entries too large to hold).
bool writeOra(const QString &path, const QByteArray &stackXml, const Entries &entries,
              const std::function<bool(QuaZip &)> &write = {},
              const QByteArray &mimetype = "image/openraster")
{
    QuaZip zip(path);
    if (!zip.open(QuaZip::mdCreate))
        return false;
    const auto add = [&zip](const QString &name, const QByteArray &bytes, int method) {
        QuaZipFile file(&zip);
        if (!file.open(QIODevice::WriteOnly, QuaZipNewInfo(name), nullptr, 0, method))
            return false;
        const bool ok = file.write(bytes) == bytes.size();
        file.close();
        return ok && file.getZipError() == UNZ_OK;
    };
    if (!mimetype.isEmpty() && !add(QStringLiteral("mimetype"), mimetype, 0))
        return false;
    if (!stackXml.isNull() && !add(QStringLiteral("stack.xml"), stackXml, Z_DEFLATED))
        return false;
    for (const auto &[name, bytes] : entries)
        if (!add(name, bytes, Z_DEFLATED))
            return false;
    if (write && !write(zip))
        return false;
    zip.close();
    return zip.getZipError() == UNZ_OK;
}

QByteArray stackOf(const QByteArray &layers)
{
    return "<?xml version='1.0' encoding='UTF-8'?>\n<image w=\"300\" h=\"200\" version=\"0.0.5\">"
           "<stack>" +
           layers + "</stack></image>";
}

// Peak resident memory (VmHWM) of this process, in bytes; reset first when the kernel allows.
qint64 statusField(const char *field)
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith(field))
            return line.mid(qsizetype(std::strlen(field)))
                       .trimmed()
                       .split(' ')
                       .front()
                       .toLongLong() *
                   1024;
    return 0;
}

// How far the peak resident memory rose above the memory in use before `work` ran.
qint64 peakGrowth(const std::function<void()> &work)
{
    QFile clear(QStringLiteral("/proc/self/clear_refs"));
    if (clear.open(QIODevice::WriteOnly))
        clear.write("5"); // resets VmHWM to the current VmRSS
    clear.close();
    const qint64 before = statusField("VmRSS:");
    work();
    return statusField("VmHWM:") - before;
}

quint32 crc32Of(const QByteArray &bytes)
{
    quint32 crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= quint8(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

QByteArray bigEndian(quint32 v)
{
    const char b[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    return QByteArray(b, 4);
}

QByteArray pngChunk(const QByteArray &type, const QByteArray &data)
{
    return bigEndian(quint32(data.size())) + type + data + bigEndian(crc32Of(type + data));
}

// A PNG whose header claims width × height RGBA pixels, followed by a little real image data
// (one deflated row of zeros) and IEND: a reader that trusts the header allocates it all.
QByteArray pngClaiming(quint32 width, quint32 height)
{
    QByteArray ihdr = bigEndian(width) + bigEndian(height);
    ihdr += QByteArray("\x08\x06\x00\x00\x00", 5); // 8 bits, RGBA, deflate, no filter, no interlace
    const QByteArray row = qCompress(QByteArray(1 + 4 * 64, '\0')).mid(4); // zlib stream
    return QByteArray("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", row) +
           pngChunk("IEND", {});
}

// Sets the uncompressed size recorded for `name` in its local header and the central directory.
bool patchClaimedSize(const QString &path, const QByteArray &name, quint32 claimed)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadWrite))
        return false;
    QByteArray zip = file.readAll();
    const char size[4] = {char(claimed), char(claimed >> 8), char(claimed >> 16),
                          char(claimed >> 24)};
    int patched = 0;
    for (qsizetype at = 0; (at = zip.indexOf("PK", at)) >= 0; ++at) {
        if (zip.mid(at, 4) == QByteArray("PK\x03\x04", 4) &&
            zip.mid(at + 30, name.size()) == name) {
            std::memcpy(zip.data() + at + 22, size, 4);
            ++patched;
        } else if (zip.mid(at, 4) == QByteArray("PK\x01\x02", 4) &&
                   zip.mid(at + 46, name.size()) == name) {
            std::memcpy(zip.data() + at + 24, size, 4);
            ++patched;
        }
    }
    file.seek(0);
    return patched == 2 && file.write(zip) == zip.size();
}

// Streams `megabytes` MB of zeros into the entry `name` (deflate shrinks them ~1000×).
std::function<bool(QuaZip &)> zerosEntry(const QString &name, int megabytes)
{
    return [=](QuaZip &zip) {
        QuaZipFile file(&zip);
        if (!file.open(QIODevice::WriteOnly, QuaZipNewInfo(name), nullptr, 0, Z_DEFLATED, 1))
            return false;
        const QByteArray megabyte(1 << 20, '\0');
        for (int i = 0; i < megabytes; ++i)
            if (file.write(megabyte) != megabyte.size())
                return false;
        file.close();
        return file.getZipError() == UNZ_OK;
    };
}

constexpr qint64 kMemoryBound = qint64(64) << 20;

} // namespace

class TestPictureImport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void plainPicturesAreOneLayer();
    void formatsOnlyFfmpegReads();
    void oraStackFlattenedBottomFirst();
    void oraLayerWithoutNameOrOffsets();
    void truncatedFilesRefused();
    void hugeClaimedSizeRefusedWithoutAllocating();
    void zipBombRefusedWithBoundedMemory();
    void lyingZipEntryRefused();
    void decodedBudgetAcrossLayers();
    void malformedOraRefused_data();
    void malformedOraRefused();

private:
    QTemporaryDir m_dir;
    QString path(const QString &name) const { return m_dir.filePath(name); }
};

void TestPictureImport::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

void TestPictureImport::plainPicturesAreOneLayer()
{
    const QImage original = patterned(64, 48, qRgb(10, 20, 30));
    QVERIFY(writeFile(path("cat.png"), encoded(original, "PNG")));
    const auto png = readPictureLayers(path("cat.png"));
    QVERIFY2(png.hasValue(), png ? "" : qPrintable(png.error()));
    QCOMPARE(png->size(), std::size_t(1));
    const PictureLayer &layer = png->front();
    QCOMPARE(layer.name, QStringLiteral("cat"));
    QCOMPARE(layer.offset, QPoint(0, 0));
    QCOMPARE(layer.image.format(), QImage::Format_ARGB32_Premultiplied);
    QCOMPARE(layer.image, original.convertToFormat(QImage::Format_ARGB32_Premultiplied));

    // JPEG: opaque, lossy; close to the original's colours.
    const QImage opaque =
        patterned(64, 48, qRgb(200, 100, 50)).convertToFormat(QImage::Format_RGB32);
    QVERIFY(writeFile(path("dog.jpg"), encoded(opaque, "JPEG", 95)));
    const auto jpeg = readPictureLayers(path("dog.jpg"));
    QVERIFY(jpeg.hasValue());
    QCOMPARE(jpeg->front().name, QStringLiteral("dog"));
    QCOMPARE(jpeg->front().image.size(), opaque.size());
    QCOMPARE(jpeg->front().image.format(), QImage::Format_ARGB32_Premultiplied);
    double error = 0.0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            error += std::abs(qGreen(jpeg->front().image.pixel(x, y)) - qGreen(opaque.pixel(x, y)));
    QVERIFY2(error / (64 * 48) < 12.0, qPrintable(QString::number(error / (64 * 48))));
    QCOMPARE(qAlpha(jpeg->front().image.pixel(5, 5)), 255);

    // GIF: a few colours and full transparency survive exactly.
    const QRgb palette[3] = {qRgb(255, 0, 0), qRgb(0, 0, 255), qRgb(0, 128, 0)};
    const auto gifIndex = [](int x, int y) { return x >= 10 ? 3 : (x + y) % 3; };
    QVERIFY(writeFile(path("few.colours.gif"), handMadeGif(20, 10, gifIndex, palette)));
    QImage few(20, 10, QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 20; ++x)
            few.setPixel(x, y, gifIndex(x, y) == 3 ? qRgba(0, 0, 0, 0) : palette[gifIndex(x, y)]);
    const auto gif = readPictureLayers(path("few.colours.gif"));
    QVERIFY2(gif.hasValue(), gif ? "" : qPrintable(gif.error()));
    QCOMPARE(gif->front().name, QStringLiteral("few.colours"));
    QCOMPARE(gif->front().offset, QPoint(0, 0));
    QCOMPARE(gif->front().image, few);
}

void TestPictureImport::formatsOnlyFfmpegReads()
{
    // Qt has no WebP or TIFF reader here; FFmpeg (through the reference layer's decoder) reads
    // them. The ffmpeg program writes them.
    if (QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
        QSKIP("needs the ffmpeg program to write WebP and TIFF");
    const QImage original = patterned(40, 30, qRgb(90, 60, 30));
    QVERIFY(writeFile(path("source.png"), encoded(original, "PNG")));
    for (const QString &name : {QStringLiteral("lossless.webp"), QStringLiteral("scan.tiff")}) {
        QStringList args{"-v", "error", "-y", "-i", path("source.png")};
        if (name.endsWith(QLatin1String("webp")))
            args << "-lossless"
                 << "1";
        args << path(name);
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), args);
        if (!ffmpeg.waitForFinished(60000) || ffmpeg.exitCode() != 0)
            QSKIP("this ffmpeg cannot write WebP or TIFF");
        const auto read = readPictureLayers(path(name));
        QVERIFY2(read.hasValue(), read ? "" : qPrintable(read.error()));
        QCOMPARE(read->size(), std::size_t(1));
        QCOMPARE(read->front().image.size(), original.size());
        const QImage expected = original.convertToFormat(QImage::Format_ARGB32_Premultiplied);
        int worst = 0;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                const QRgb a = read->front().image.pixel(x, y), b = expected.pixel(x, y);
                worst = std::max({worst, std::abs(qAlpha(a) - qAlpha(b)),
                                  std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b))});
            }
        QVERIFY2(worst <= 1, qPrintable(name + QStringLiteral(": %1").arg(worst)));
    }
}

void TestPictureImport::oraStackFlattenedBottomFirst()
{
    const QImage head = patterned(30, 20, qRgb(250, 200, 0));
    const QImage body = patterned(50, 60, qRgb(0, 50, 100));
    QImage arm(12, 8, QImage::Format_ARGB32);
    arm.fill(qRgba(0, 200, 40, 255));
    const QByteArray xml = stackOf(
        "<layer name=\"head\" src=\"data/head.png\" x=\"50\" y=\"5\" opacity=\"1.0\" "
        "visibility=\"visible\"/>"
        "<layer name=\"ghost\" src=\"data/ghost.png\" x=\"0\" y=\"0\" visibility=\"hidden\"/>"
        "<stack name=\"limbs\" x=\"10\" y=\"20\" opacity=\"0.5\">"
        "  <layer name=\"left arm\" src=\"data/arm.png\" x=\"30\" y=\"40\" opacity=\"0.5\"/>"
        "  <stack name=\"hidden group\" x=\"1\" y=\"1\" visibility=\"hidden\">"
        "    <layer name=\"secret\" src=\"data/secret.png\"/>" // not even in the zip
        "  </stack>"
        "  <text>not a picture</text>"
        "</stack>"
        "<layer name=\"body\" src=\"data/body.png\" x=\"40\" y=\"30\" "
        "composite-op=\"svg:src-over\"/>");
    QVERIFY(writeOra(path("character.ora"), xml,
                     {{"data/head.png", encoded(head, "PNG")},
                      {"data/ghost.png", encoded(body, "PNG")},
                      {"data/arm.png", encoded(arm, "PNG")},
                      {"data/body.png", encoded(body, "PNG")}}));
    const auto layers = readPictureLayers(path("character.ora"));
    QVERIFY2(layers.hasValue(), layers ? "" : qPrintable(layers.error()));
    QCOMPARE(layers->size(), std::size_t(3));
    const PictureLayer &bottom = (*layers)[0], &middle = (*layers)[1], &top = (*layers)[2];
    QCOMPARE(bottom.name, QStringLiteral("body"));
    QCOMPARE(middle.name, QStringLiteral("left arm"));
    QCOMPARE(top.name, QStringLiteral("head"));
    QCOMPARE(bottom.offset, QPoint(40, 30));
    QCOMPARE(middle.offset, QPoint(40, 60)); // the stack's 10, 20 plus the layer's 30, 40
    QCOMPARE(top.offset, QPoint(50, 5));
    QCOMPARE(bottom.image, body.convertToFormat(QImage::Format_ARGB32_Premultiplied));
    QCOMPARE(top.image, head.convertToFormat(QImage::Format_ARGB32_Premultiplied));
    // The arm's opacity 0.5 within a stack of opacity 0.5: a quarter, premultiplied.
    QCOMPARE(middle.image.size(), arm.size());
    QCOMPARE(middle.image.format(), QImage::Format_ARGB32_Premultiplied);
    for (const QPoint p : {QPoint(0, 0), QPoint(11, 7), QPoint(5, 3)}) {
        const QRgb c = middle.image.pixel(p);
        QVERIFY(std::abs(qAlpha(c) - 64) <= 1);
        QVERIFY(std::abs(qGreen(c) - 50) <= 1);
        QVERIFY(std::abs(qBlue(c) - 10) <= 1);
        QCOMPARE(qRed(c), 0);
    }
}

void TestPictureImport::oraLayerWithoutNameOrOffsets()
{
    // No name: the picture's base name; no x, y or opacity: 0, 0 and opaque. Fractional
    // positions (some writers) are rounded. No mimetype entry is tolerated.
    const QImage one = patterned(8, 8, qRgb(1, 2, 3));
    const QByteArray xml = stackOf("<layer src=\"data/sky.png\"/>"
                                   "<layer name=\"ground\" src=\"data/ground.png\" x=\"3.0\" "
                                   "y=\"-7.4\"/>");
    QVERIFY(
        writeOra(path("plain.ora"), xml,
                 {{"data/sky.png", encoded(one, "PNG")}, {"data/ground.png", encoded(one, "PNG")}},
                 {}, QByteArray()));
    const auto layers = readPictureLayers(path("plain.ora"));
    QVERIFY2(layers.hasValue(), layers ? "" : qPrintable(layers.error()));
    QCOMPARE(layers->size(), std::size_t(2));
    QCOMPARE((*layers)[0].name, QStringLiteral("ground"));
    QCOMPARE((*layers)[0].offset, QPoint(3, -7));
    QCOMPARE((*layers)[1].name, QStringLiteral("sky"));
    QCOMPARE((*layers)[1].offset, QPoint(0, 0));
    QCOMPARE((*layers)[1].image, one.convertToFormat(QImage::Format_ARGB32_Premultiplied));
}

void TestPictureImport::truncatedFilesRefused()
{
    QImage noise(200, 200, QImage::Format_ARGB32);
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x)
            noise.setPixel(x, y, qRgba(x * 7 % 256, y * 13 % 256, (x * y) % 256, 255));
    const QByteArray png = encoded(noise, "PNG");
    QVERIFY(writeFile(path("cut.png"), png.left(png.size() / 2)));
    const auto cut = readPictureLayers(path("cut.png"));
    QVERIFY(!cut);
    QVERIFY2(cut.error().contains(QLatin1String("cut.png")), qPrintable(cut.error()));
    QVERIFY2(cut.error().contains(QLatin1String("cut short")), qPrintable(cut.error()));

    // A JPEG cut short: Qt's reader would fill the missing rows with grey.
    const QByteArray jpeg = encoded(noise.convertToFormat(QImage::Format_RGB32), "JPEG", 90);
    QVERIFY(writeFile(path("cut.jpg"), jpeg.left(jpeg.size() / 2)));
    const auto cutJpeg = readPictureLayers(path("cut.jpg"));
    QVERIFY(!cutJpeg);
    QVERIFY2(cutJpeg.error().contains(QLatin1String("cut short")), qPrintable(cutJpeg.error()));
    QVERIFY(writeFile(path("whole.jpg"), jpeg));
    QVERIFY(readPictureLayers(path("whole.jpg")).hasValue());

    QVERIFY(writeOra(path("whole.ora"), stackOf("<layer name=\"a\" src=\"a.png\"/>"),
                     {{"a.png", png}}));
    QFile whole(path("whole.ora"));
    QVERIFY(whole.open(QIODevice::ReadOnly));
    const QByteArray zip = whole.readAll();
    for (const double part : {0.3, 0.9, 0.999}) {
        QVERIFY(writeFile(path("cut.ora"), zip.left(qsizetype(zip.size() * part))));
        const auto ora = readPictureLayers(path("cut.ora"));
        QVERIFY(!ora);
        QVERIFY2(ora.error().contains(QLatin1String("cut.ora")), qPrintable(ora.error()));
    }
    QVERIFY(writeFile(path("words.ora"), "Not a zip archive at all."));
    const auto words = readPictureLayers(path("words.ora"));
    QVERIFY(!words);
    QVERIFY2(words.error().contains(QLatin1String("zip")), qPrintable(words.error()));
    QVERIFY(writeFile(path("empty.png"), {}));
    QVERIFY(!readPictureLayers(path("empty.png")));
    QVERIFY(!readPictureLayers(path("not-there.png")));
    QVERIFY(writeFile(path("text.png"), "This is not a picture at all, only words."));
    const auto text = readPictureLayers(path("text.png"));
    QVERIFY(!text);
    QVERIFY(text.error().contains(QLatin1String("text.png")));
}

void TestPictureImport::hugeClaimedSizeRefusedWithoutAllocating()
{
    // 50,000 × 50,000 RGBA would be 10 GB decoded; the header alone must refuse it.
    const QByteArray png = pngClaiming(50000, 50000);
    QVERIFY(writeFile(path("huge.png"), png));
    Expected<std::vector<PictureLayer>, QString> read = unexpected(QString());
    const qint64 grew = peakGrowth([&] { read = readPictureLayers(path("huge.png")); });
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("50000")), qPrintable(read.error()));
    QVERIFY2(read.error().contains(QLatin1String("huge.png")), qPrintable(read.error()));
    QVERIFY2(grew < kMemoryBound, qPrintable(QString::number(grew)));

    // The same picture as a layer of an OpenRaster file.
    QVERIFY(writeOra(path("huge.ora"), stackOf("<layer name=\"sky\" src=\"data/sky.png\"/>"),
                     {{"data/sky.png", png}}));
    const qint64 grewOra = peakGrowth([&] { read = readPictureLayers(path("huge.ora")); });
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("sky")), qPrintable(read.error()));
    QVERIFY2(read.error().contains(QLatin1String("50000")), qPrintable(read.error()));
    QVERIFY2(grewOra < kMemoryBound, qPrintable(QString::number(grewOra)));

    // Just past the side limit, and within the sides but past the pixel limit.
    QVERIFY(writeFile(path("wide.png"), pngClaiming(16385, 16)));
    QVERIFY(!readPictureLayers(path("wide.png")));
    QVERIFY(writeFile(path("square.png"), pngClaiming(9000, 9000)));
    const auto square = readPictureLayers(path("square.png"));
    QVERIFY(!square);
    QVERIFY2(square.error().contains(QLatin1String("megapixels")), qPrintable(square.error()));
}

void TestPictureImport::zipBombRefusedWithBoundedMemory()
{
    // 400 MB of zeros in one layer "PNG": ~400 KB in the zip.
    QVERIFY(writeOra(path("bomb.ora"), stackOf("<layer name=\"bomb\" src=\"data/bomb.png\"/>"), {},
                     zerosEntry(QStringLiteral("data/bomb.png"), 400)));
    QVERIFY(QFileInfo(path("bomb.ora")).size() < (qint64(4) << 20));
    Expected<std::vector<PictureLayer>, QString> read = unexpected(QString());
    QElapsedTimer clock;
    clock.start();
    const qint64 grew = peakGrowth([&] { read = readPictureLayers(path("bomb.ora")); });
    QVERIFY(!read);
    QVERIFY2(grew < kMemoryBound, qPrintable(QString::number(grew)));
    QVERIFY2(read.error().contains(QLatin1String("bomb")), qPrintable(read.error()));
    QVERIFY2(read.error().contains(QLatin1String("larger than")), qPrintable(read.error()));
    qInfo("zip bomb refused in %lld ms, peak memory +%lld KB", qint64(clock.elapsed()),
          grew / 1024);

    // The same bomb as stack.xml.
    QVERIFY(writeOra(path("xml-bomb.ora"), QByteArray(), {},
                     zerosEntry(QStringLiteral("stack.xml"), 64)));
    const qint64 grewXml = peakGrowth([&] { read = readPictureLayers(path("xml-bomb.ora")); });
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("stack.xml")), qPrintable(read.error()));
    QVERIFY2(grewXml < kMemoryBound, qPrintable(QString::number(grewXml)));
}

void TestPictureImport::lyingZipEntryRefused()
{
    // 300 MB of zeros whose headers claim 1,000 bytes: the reader stops at what is claimed and
    // the checksum shows the lie; it never holds the 300 MB.
    QVERIFY(writeOra(path("liar.ora"), stackOf("<layer name=\"liar\" src=\"data/liar.png\"/>"), {},
                     zerosEntry(QStringLiteral("data/liar.png"), 300)));
    QVERIFY(patchClaimedSize(path("liar.ora"), "data/liar.png", 1000));
    Expected<std::vector<PictureLayer>, QString> read = unexpected(QString());
    const qint64 grew = peakGrowth([&] { read = readPictureLayers(path("liar.ora")); });
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("liar")), qPrintable(read.error()));
    QVERIFY2(read.error().contains(QLatin1String("damaged")), qPrintable(read.error()));
    QVERIFY2(grew < kMemoryBound, qPrintable(QString::number(grew)));

    // A real PNG whose headers claim 100 MB: the bytes run out before the claim.
    const QByteArray png = encoded(patterned(16, 16, qRgb(5, 5, 5)), "PNG");
    QVERIFY(writeOra(path("boaster.ora"), stackOf("<layer name=\"boaster\" src=\"b.png\"/>"),
                     {{"b.png", png}}));
    QVERIFY(patchClaimedSize(path("boaster.ora"), "b.png", 100u << 20));
    const qint64 grewBoast = peakGrowth([&] { read = readPictureLayers(path("boaster.ora")); });
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("damaged")), qPrintable(read.error()));
    QVERIFY2(grewBoast < kMemoryBound, qPrintable(QString::number(grewBoast)));
}

void TestPictureImport::decodedBudgetAcrossLayers()
{
    // Three transparent 5000 × 5000 layers: 100 MB each decoded, 300 MB together, past the
    // 256 MB budget; the third is refused before it is decoded.
    QImage clear(5000, 5000, QImage::Format_ARGB32);
    clear.fill(Qt::transparent);
    const QByteArray png = encoded(clear, "PNG");
    clear = QImage();
    QVERIFY(writeOra(path("three.ora"),
                     stackOf("<layer name=\"c\" src=\"c.png\"/><layer name=\"b\" src=\"b.png\"/>"
                             "<layer name=\"a\" src=\"a.png\"/>"),
                     {{"a.png", png}, {"b.png", png}, {"c.png", png}}));
    const auto three = readPictureLayers(path("three.ora"));
    QVERIFY(!three);
    QVERIFY2(three.error().contains(QStringLiteral("“c”")), qPrintable(three.error()));
    QVERIFY2(three.error().contains(QLatin1String("MB")), qPrintable(three.error()));
    // Two fit.
    QVERIFY(writeOra(path("two.ora"),
                     stackOf("<layer name=\"b\" src=\"b.png\"/><layer name=\"a\" src=\"a.png\"/>"),
                     {{"a.png", png}, {"b.png", png}}));
    const auto two = readPictureLayers(path("two.ora"));
    QVERIFY2(two.hasValue(), two ? "" : qPrintable(two.error()));
    QCOMPARE(two->size(), std::size_t(2));
}

void TestPictureImport::malformedOraRefused_data()
{
    QTest::addColumn<QByteArray>("xml");
    QTest::addColumn<bool>("withLayer");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<QByteArray>("mimetype");
    const QByteArray ora = "image/openraster";
    const QByteArray good = "<layer name=\"a\" src=\"a.png\"/>";
    QTest::newRow("no stack.xml") << QByteArray() << true << "stack.xml" << ora;
    QTest::newRow("malformed xml")
        << QByteArray("<image><stack><layer src=\"a.png\"></stack>") << true << "malformed" << ora;
    QTest::newRow("not xml") << QByteArray("\x00\x01garbage", 9) << true << "stack.xml" << ora;
    QTest::newRow("wrong root") << QByteArray("<svg><stack/></svg>") << true << "OpenRaster" << ora;
    QTest::newRow("empty stack") << stackOf("") << true << "empty" << ora;
    QTest::newRow("all hidden") << stackOf("<layer src=\"a.png\" visibility=\"hidden\"/>") << true
                                << "no visible layer" << ora;
    QTest::newRow("transparent") << stackOf("<layer src=\"a.png\" opacity=\"0\"/>") << true
                                 << "no visible layer" << ora;
    QTest::newRow("picture missing") << stackOf(good) << false << "missing" << ora;
    QTest::newRow("layer without src")
        << stackOf("<layer name=\"x\"/>") << true << "without" << ora;
    QTest::newRow("bad position") << stackOf("<layer src=\"a.png\" x=\"1e300\"/>") << true
                                  << "position" << ora;
    QTest::newRow("bad opacity") << stackOf("<layer src=\"a.png\" opacity=\"nan\"/>") << true
                                 << "opacity" << ora;
    QByteArray deep;
    for (int i = 0; i < 100; ++i)
        deep += "<stack>";
    deep += good;
    for (int i = 0; i < 100; ++i)
        deep += "</stack>";
    QTest::newRow("nested too deeply") << stackOf(deep) << true << "nested" << ora;
    QByteArray many;
    for (int i = 0; i < 1001; ++i)
        many += good;
    QTest::newRow("too many layers") << stackOf(many) << true << "1000 layers" << ora;
    QTest::newRow("other mimetype")
        << stackOf(good) << true << "not an OpenRaster" << QByteArray("application/x-krita");
}

void TestPictureImport::malformedOraRefused()
{
    QFETCH(QByteArray, xml);
    QFETCH(bool, withLayer);
    QFETCH(QString, expected);
    QFETCH(QByteArray, mimetype);
    Entries entries;
    if (withLayer)
        entries.emplace_back(QStringLiteral("a.png"),
                             encoded(patterned(4, 4, qRgb(9, 9, 9)), "PNG"));
    QVERIFY(writeOra(path("bad.ora"), xml, entries, {}, mimetype));
    const auto read = readPictureLayers(path("bad.ora"));
    QVERIFY(!read);
    QVERIFY2(read.error().contains(QLatin1String("bad.ora")), qPrintable(read.error()));
    QVERIFY2(read.error().contains(expected), qPrintable(read.error()));
}

QTEST_GUILESS_MAIN(TestPictureImport)
#include "tst_picture_import.moc"
