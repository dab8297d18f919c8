// The HTML flipbook's soundtrack in a real browser: headless Chromium opens the exported page
// (autoplay allowed, as after a click), a small script added to the page drives it through
// window.flipbook and writes what the <audio> element did into the DOM, which --dump-dom
// returns. The sound decodes with the length of the exported range, starts with the frames at
// the frame's time, and stops on pause, on a step and stays silent while scrubbed. Skips when
// Chromium is missing (.ci/setup installs it).
#include "export_support.h"
#include "sound_support.h"

#include <finbook/model/export/exporter.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QUrl>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {

// Drives the flipbook once its sound's length is known; each step's state goes into
// <pre id="result"> as JSON. The page's own policy allows inline scripts only, as this is.
constexpr char kProbe[] = R"JS(
<pre id="result">waiting</pre>
<script>
"use strict";
(function () {
  const audio = document.getElementById("sound");
  const steps = [];
  function record(name) {
    const f = window.flipbook, s = f.sound;
    steps.push({name: name, tick: f.tick, playing: f.playing, paused: s.paused,
                time: s.time, duration: s.duration});
    document.getElementById("result").textContent = JSON.stringify(steps);
  }
  function run() {
    record("opened");
    flipbook.seek(3);
    flipbook.play();
    setTimeout(() => {
      record("playing");
      flipbook.seek(5);
      record("moved while playing");
      flipbook.pause();
      record("paused");
      const scrub = document.getElementById("scrub");
      scrub.value = "6";
      scrub.dispatchEvent(new Event("input"));
      record("scrubbed while paused");
      flipbook.play();
      record("played again");
      document.dispatchEvent(new KeyboardEvent("keydown", {key: "ArrowLeft"}));
      record("stepped");
    }, 150);
  }
  if (audio.readyState >= 1) run(); else audio.addEventListener("loadedmetadata", run);
})();
</script>
)JS";

QJsonArray runInChromium(const QString &page)
{
    QTemporaryDir profile;
    QProcess p;
    p.start(chromium(),
            {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
             QStringLiteral("--disable-gpu"), QStringLiteral("--no-first-run"),
             QStringLiteral("--disable-background-networking"),
             QStringLiteral("--disable-component-update"), QStringLiteral("--disable-sync"),
             QStringLiteral("--autoplay-policy=no-user-gesture-required"),
             QStringLiteral("--user-data-dir=") + profile.path(),
             QStringLiteral("--virtual-time-budget=3000"), QStringLiteral("--dump-dom"),
             QUrl::fromLocalFile(page).toString() + QStringLiteral("#paused")});
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return {};
    }
    const QString dom = QString::fromUtf8(p.readAllStandardOutput());
    static const QRegularExpression result(QStringLiteral("<pre id=\"result\">([^<]*)</pre>"));
    const auto match = result.match(dom);
    if (!match.hasMatch()) {
        qWarning("no result in the page: %s", qPrintable(dom.left(400)));
        return {};
    }
    // --dump-dom escapes the text as HTML.
    QString json = match.captured(1);
    json.replace(QStringLiteral("&quot;"), QStringLiteral("\""))
        .replace(QStringLiteral("&amp;"), QStringLiteral("&"));
    return QJsonDocument::fromJson(json.toUtf8()).array();
}

} // namespace

class TestExportHtmlSound : public QObject {
    Q_OBJECT
private slots:
    void soundPlaysWithTheFramesOnly();
};

void TestExportHtmlSound::soundPlaysWithTheFramesOnly()
{
    if (chromium().isEmpty())
        QSKIP("Chromium not installed (bash .ci/setup installs it)");
    model::ExportSource source = loadExample(); // 12 frames at 12 fps
    QCOMPARE(source.frames.size(), std::size_t(12));
    source.settings.fps = 12;
    model::SoundClip clip; // two seconds of sine from the start
    clip.id = 1000;
    clip.name = QStringLiteral("beat.wav");
    clip.bytes = sound_test::sineWav(2.0);
    source.sound = {clip};
    QTemporaryDir dir;
    model::ExportOptions o;
    o.format = model::ExportFormat::Html;
    o.target = dir.filePath(QStringLiteral("sound.html"));
    o.firstFrame = 2; // frames 3 … 10: 8 ticks, 2/3 s
    o.lastFrame = 9;
    o.scale = 0.25;
    QVERIFY(model::exportAnimation(source, o));
    QFile f(o.target);
    QVERIFY(f.open(QIODevice::ReadWrite));
    QByteArray html = f.readAll();
    QVERIFY(html.contains("<audio id=\"sound\""));
    html.replace("</body>", QByteArray(kProbe) + "</body>");
    QVERIFY(f.resize(0));
    QVERIFY(f.write(html) == html.size());
    f.close();

    const QJsonArray steps = runInChromium(o.target);
    qInfo("%s", QJsonDocument(steps).toJson(QJsonDocument::Compact).constData());
    QCOMPARE(steps.size(), 7);
    const auto step = [&](int i) { return steps.at(i).toObject(); };
    const auto number = [&](int i, const char *key) {
        return step(i)[QLatin1String(key)].toDouble();
    };
    const auto flag = [&](int i, const char *key) { return step(i)[QLatin1String(key)].toBool(); };
    // Opened paused: silent, and the <audio> decodes to the range's length (8 ticks at 12 fps).
    QVERIFY(!flag(0, "playing"));
    QVERIFY(flag(0, "paused"));
    QVERIFY2(std::abs(number(0, "duration") - 8.0 / 12) < 0.02,
             qPrintable(QString::number(number(0, "duration"))));
    // Play from tick 3: the sound plays from 3/12 s with the frames.
    QVERIFY(flag(1, "playing"));
    QVERIFY(!flag(1, "paused"));
    QVERIFY(number(1, "time") >= 3.0 / 12 - 0.01);
    // Moved while playing: the sound follows the frame.
    QVERIFY(!flag(2, "paused"));
    QVERIFY(std::abs(number(2, "time") - 5.0 / 12) < 0.01);
    // Pause: silent; scrubbing while paused stays silent and moves the frame.
    QVERIFY(!flag(3, "playing"));
    QVERIFY(flag(3, "paused"));
    QCOMPARE(number(4, "tick"), 6.0);
    QVERIFY(flag(4, "paused"));
    // Played again from the scrubbed frame, then a step with the arrow key stops it.
    QVERIFY(!flag(5, "paused"));
    QVERIFY(std::abs(number(5, "time") - 6.0 / 12) < 0.01);
    QVERIFY(!flag(6, "playing"));
    QVERIFY(flag(6, "paused"));
}

QTEST_GUILESS_MAIN(TestExportHtmlSound)
#include "tst_export_html_sound.moc"
