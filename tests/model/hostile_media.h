// Hostile embedded media for the limits tests (issue 47), each made here: SVG that asks for
// text, time or millions of elements, and a video whose frames are far larger than its
// header says. Small files, every one of them; what they cost is what the tests measure.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>

namespace hostile_media {

// A small SVG with text: drawing it needs the font database.
inline QByteArray svgWithText()
{
    return QByteArrayLiteral(
        "<?xml version=\"1.0\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"120\" height=\"80\">"
        "<rect width=\"120\" height=\"80\" fill=\"#ffd0d0\"/>"
        "<text x=\"10\" y=\"50\" font-size=\"30\" fill=\"#000080\">Hi!</text></svg>\n");
}

// `rects` translucent rectangles each covering the whole `side`-px picture: painting it
// costs rects × side² pixels (3,000 at 4,096 px: about 50 billion), from ~150 KB of XML.
inline QByteArray slowSvg(int rects = 3000, int side = 4096)
{
    QByteArray svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                     QByteArray::number(side) + "\" height=\"" + QByteArray::number(side) + "\">";
    for (int i = 0; i < rects; ++i)
        svg += "<rect width=\"" + QByteArray::number(side) + "\" height=\"" +
               QByteArray::number(side) + "\" fill=\"#" +
               QByteArray::number(0x100000 + i * 77, 16) + "\" fill-opacity=\"0.03\"/>";
    return svg + "</svg>\n";
}

// Ten levels of ten <use> each: 10^10 painted rectangles from about 2 KB.
inline QByteArray useBomb()
{
    QByteArray svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                     "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"100\" height=\"100\">"
                     "<defs><rect id=\"l0\" width=\"1\" height=\"1\" fill=\"red\"/>";
    for (int level = 1; level <= 10; ++level) {
        svg += "<g id=\"l" + QByteArray::number(level) + "\">";
        for (int i = 0; i < 10; ++i)
            svg += "<use xlink:href=\"#l" + QByteArray::number(level - 1) + "\"/>";
        svg += "</g>";
    }
    return svg + "</defs><use xlink:href=\"#l10\"/></svg>\n";
}

// A <use> that refers to itself through a group.
inline QByteArray useLoop()
{
    return QByteArrayLiteral("<svg xmlns=\"http://www.w3.org/2000/svg\" "
                             "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"50\" "
                             "height=\"50\"><g id=\"a\"><rect width=\"5\" height=\"5\"/>"
                             "<use xlink:href=\"#a\" x=\"5\"/></g></svg>\n");
}

// An AVI of MJPEG whose header says 64 × 64 (its first picture) and whose later pictures
// are `wide` × 1000 px, made by ffmpeg from pictures it draws; empty when ffmpeg is missing.
inline QByteArray lyingVideo(const QTemporaryDir &dir, int wide = 16000)
{
    const QString ffmpeg = QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
    if (ffmpeg.isEmpty())
        return {};
    const auto run = [&](const QStringList &arguments) {
        QProcess p;
        p.start(ffmpeg,
                QStringList{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y")} +
                    arguments);
        return p.waitForFinished(120000) && p.exitCode() == 0;
    };
    const QString small = dir.filePath(QStringLiteral("small.jpg"));
    const QString large = dir.filePath(QStringLiteral("large.jpg"));
    if (!run({QStringLiteral("-f"), QStringLiteral("lavfi"), QStringLiteral("-i"),
              QStringLiteral("color=red:s=64x64"), QStringLiteral("-frames"), QStringLiteral("1"),
              QStringLiteral("-q:v"), QStringLiteral("20"), small}) ||
        !run({QStringLiteral("-f"), QStringLiteral("lavfi"), QStringLiteral("-i"),
              QStringLiteral("color=blue:s=%1x1000").arg(wide), QStringLiteral("-frames"),
              QStringLiteral("1"), QStringLiteral("-q:v"), QStringLiteral("31"), large}))
        return {};
    QFile a(small), b(large);
    if (!a.open(QIODevice::ReadOnly) || !b.open(QIODevice::ReadOnly))
        return {};
    QByteArray raw = a.readAll();
    const QByteArray big = b.readAll();
    for (int i = 0; i < 7; ++i)
        raw += big;
    const QString rawPath = dir.filePath(QStringLiteral("lying.mjpeg"));
    const QString avi = dir.filePath(QStringLiteral("lying.avi"));
    QFile out(rawPath);
    if (!out.open(QIODevice::WriteOnly) || out.write(raw) != raw.size())
        return {};
    out.close();
    if (!run({QStringLiteral("-f"), QStringLiteral("mjpeg"), QStringLiteral("-framerate"),
              QStringLiteral("4"), QStringLiteral("-i"), rawPath, QStringLiteral("-c"),
              QStringLiteral("copy"), avi}))
        return {};
    QFile f(avi);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace hostile_media
