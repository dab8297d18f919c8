// Shared by the reference tests: generated pictures and videos, and a small document.
#pragma once

#include <finbook/model/document.h>
#include <finbook/model/reference/reference_layer.h>

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

namespace finbook::test {

// A PNG of `size` pixels: red left half, blue right half.
inline QString writeTwoColourPng(const QString &folder, QSize size = QSize(80, 60))
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::red);
    for (int y = 0; y < size.height(); ++y)
        for (int x = size.width() / 2; x < size.width(); ++x)
            image.setPixel(x, y, qRgb(0, 0, 255));
    const QString path = QDir(folder).filePath(QStringLiteral("two.png"));
    image.save(path);
    return path;
}

// ffmpeg's testsrc as a video file; empty when ffmpeg is missing or fails.
inline QString writeTestVideo(const QString &folder, const QString &name, QSize size,
                              double seconds, int fps, int gop = 12)
{
    const QString ffmpeg = QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
    if (ffmpeg.isEmpty())
        return {};
    const QString path = QDir(folder).filePath(name);
    QProcess p;
    p.start(ffmpeg, {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y"),
                     QStringLiteral("-f"), QStringLiteral("lavfi"), QStringLiteral("-i"),
                     QStringLiteral("testsrc=size=%1x%2:rate=%3:duration=%4")
                         .arg(size.width())
                         .arg(size.height())
                         .arg(fps)
                         .arg(seconds),
                     QStringLiteral("-g"), QString::number(gop), QStringLiteral("-pix_fmt"),
                     QStringLiteral("yuv420p"), path});
    if (!p.waitForFinished(600000) || p.exitCode() != 0)
        return {};
    return path;
}

} // namespace finbook::test
