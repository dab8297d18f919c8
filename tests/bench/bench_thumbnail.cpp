// finbook-bench thumbnail [FILE...]: what `finbook thumbnail` costs, run as file managers run it
// (a child process, 256 px). Without FILE: the bundled example and the crafted files of
// tests/app/crafted_files.h (shaded grids at the editor's finest mesh and at the densities an
// old reader let in, a grid of 63 lines on the largest canvas, 100,000 fills), made afresh in a
// temporary folder (--write DIR: only writes them there). One JSON object per file: its size, the
// exit code, wall seconds and the child's peak resident memory (MiB); a last line gives the worst
// of each.
#include "../app/crafted_files.h"
#include "../app/limits_support.h"
#include "bench.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cstdio>

namespace {

using namespace finbook;

int benchThumbnail(const QStringList &args)
{
    QTemporaryDir dir;
    if (!dir.isValid()) {
        std::fprintf(stderr, "cannot make a temporary folder\n");
        return 1;
    }
    QStringList files = args;
    // --write DIR: only write the crafted files there (to try them elsewhere: finbook export).
    const bool writeOnly = files.size() == 2 && files.front() == QLatin1String("--write");
    const QString folder = writeOnly ? files.back() : dir.path();
    if (writeOnly)
        files.clear();
    if (files.isEmpty()) {
        files << QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
        const std::pair<const char *, QByteArray> made[] = {
            {"shaded-grid-density-4", crafted::shadedGrid(20, {1280, 720}, 4.0)},
            {"shaded-grid-density-100", crafted::shadedGrid(20, {1280, 720}, 100.0)},
            {"grid-63-lines-16384px", crafted::shadedGrid(32, {16384, 16384}, 4.0)},
            {"fills-100000", crafted::manyFills(100000)},
        };
        for (const auto &[name, bytes] : made) {
            QFile f(QDir(folder).filePath(QString::fromLatin1(name) + QStringLiteral(".finbook")));
            if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
                return 1;
            files << f.fileName();
        }
    }
    if (writeOnly) {
        std::printf("%s\n", qPrintable(files.mid(1).join(QLatin1Char('\n'))));
        return 0;
    }
    double worstSeconds = 0;
    long worstMiB = 0;
    for (const QString &file : files) {
        const QString png = dir.filePath(QStringLiteral("out.png"));
        const limits_test::Measured m = limits_test::runMeasured(
            {QStringLiteral("thumbnail"), file, png, QStringLiteral("256")});
        worstSeconds = std::max(worstSeconds, m.seconds);
        worstMiB = std::max(worstMiB, m.peakMiB);
        QJsonObject row{{QStringLiteral("bench"), QStringLiteral("thumbnail")},
                        {QStringLiteral("file"), QFileInfo(file).fileName()},
                        {QStringLiteral("file_bytes"), QFileInfo(file).size()},
                        {QStringLiteral("exit_code"), m.code},
                        {QStringLiteral("seconds"), m.seconds},
                        {QStringLiteral("peak_mib"), qint64(m.peakMiB)},
                        {QStringLiteral("png_bytes"), QFileInfo(png).size()}};
        if (!m.err.isEmpty())
            row.insert(QStringLiteral("said"), QString::fromUtf8(m.err).trimmed());
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
        QFile::remove(png);
    }
    std::printf("{\"bench\":\"thumbnail\",\"files\":%lld,\"worst_seconds\":%.3f,"
                "\"worst_peak_mib\":%ld}\n",
                qint64(files.size()), worstSeconds, worstMiB);
    return 0;
}

} // namespace

FINBOOK_BENCH("thumbnail",
              "thumbnail [FILE... | --write DIR]  (default: the example and crafted files)",
              benchThumbnail);
