// The HTML flipbook in a real browser: headless Chromium opens the exported file from disk (no
// network), shows the first frame, and after a second of play shows another one; at the end of
// a non-looping animation it rests on the last frame. Screenshots are compared with the frames
// rendered by the exporter. Skips when Chromium is missing (.ci/setup installs it).
#include "export_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>

#include <QProcess>
#include <QTemporaryDir>
#include <QUrl>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {

// Runs headless Chromium on `url` for `virtualMs` of page time; returns its screenshot.
QImage screenshot(const QString &url, int virtualMs, const QString &file)
{
    QTemporaryDir profile; // a fresh profile every run
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(chromium(),
            {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
             QStringLiteral("--disable-gpu"), QStringLiteral("--disable-quic"),
             QStringLiteral("--no-first-run"), QStringLiteral("--disable-background-networking"),
             QStringLiteral("--disable-component-update"), QStringLiteral("--disable-sync"),
             QStringLiteral("--hide-scrollbars"), QStringLiteral("--force-device-scale-factor=1"),
             QStringLiteral("--user-data-dir=") + profile.path(),
             QStringLiteral("--window-size=700,440"),
             QStringLiteral("--virtual-time-budget=%1").arg(virtualMs),
             QStringLiteral("--screenshot=") + file, url});
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return {};
    }
    return QImage(file);
}

// Index of the frame whose render is nearest to `shot`, and how near.
std::pair<int, double> nearestFrame(const QImage &shot, const std::vector<QImage> &frames)
{
    int best = -1;
    double bestDifference = 1e9;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const double d = difference(shot, frames[i]).meanAbs;
        if (d < bestDifference) {
            bestDifference = d;
            best = int(i);
        }
    }
    return {best, bestDifference};
}

} // namespace

class TestExportHtml : public QObject {
    Q_OBJECT
private slots:
    void playsInABrowser();
};

void TestExportHtml::playsInABrowser()
{
    if (chromium().isEmpty())
        QSKIP("Chromium not installed (bash .ci/setup installs it)");
    QTemporaryDir dir;
    const model::ExportSource source = exampleWithHolds(); // 12 drawings, 18 ticks, 1.5 s
    model::ExportOptions o;
    o.format = model::ExportFormat::Html;
    o.target = dir.filePath(QStringLiteral("walk.html"));
    o.scale = 0.5;
    o.loop = false; // so the end is a known frame
    QVERIFY(model::exportAnimation(source, o));
    const auto plan = model::planExport(source, o);
    std::vector<QImage> frames;
    for (const model::Frame &f : source.frames)
        frames.push_back(model::renderExportFrame(f, source.settings, *plan));

    QUrl url = QUrl::fromLocalFile(o.target);
    const QRect stage(QPoint(0, 0), plan->size); // the canvas sits at the top left, 1:1
    url.setFragment(QStringLiteral("paused"));
    const QImage first = screenshot(url.toString(), 500, dir.filePath(QStringLiteral("first.png")));
    QVERIFY2(!first.isNull(), "Chromium made no screenshot");
    const auto [firstIndex, firstDifference] = nearestFrame(first.copy(stage), frames);
    url.setFragment(QString());
    const QImage second =
        screenshot(url.toString(), 1000, dir.filePath(QStringLiteral("second.png")));
    QVERIFY(!second.isNull());
    const auto [secondIndex, secondDifference] = nearestFrame(second.copy(stage), frames);
    const QImage last = screenshot(url.toString(), 3000, dir.filePath(QStringLiteral("last.png")));
    QVERIFY(!last.isNull());
    const auto [lastIndex, lastDifference] = nearestFrame(last.copy(stage), frames);
    qInfo("paused: frame %d (mean difference %.2f); after 1 s of play: frame %d (%.2f); after 3 s: "
          "frame %d (%.2f); first vs second screenshot: %.2f",
          firstIndex + 1, firstDifference, secondIndex + 1, secondDifference, lastIndex + 1,
          lastDifference, difference(first.copy(stage), second.copy(stage)).meanAbs);
    QCOMPARE(firstIndex, 0);
    QVERIFY(firstDifference < 1.0);
    // A second into playback (12 ticks at 12 fps) the page is well past the first drawing.
    QVERIFY2(secondIndex >= 5, qPrintable(QString::number(secondIndex + 1)));
    QVERIFY(secondDifference < 1.0);
    QVERIFY(difference(first.copy(stage), second.copy(stage)).meanAbs > 5 * secondDifference);
    // Not looping: after the animation's 1.5 s it rests on the last drawing.
    QCOMPARE(lastIndex, 11);
    QVERIFY(lastDifference < 1.0);
    // The controls are drawn below the picture, not over it.
    QVERIFY(first.height() > stage.height() + 20);
}

QTEST_GUILESS_MAIN(TestExportHtml)
#include "tst_export_html.moc"
