// The Lottie export in the web's own player and against the format's published schema:
// lottie-web (Airbnb's player, npm) plays the exported JSON in headless Chromium, and each
// screenshot is compared with Finbook's export of the same tick (a pixel agrees when each
// channel is within 24/255); the Lottie Animation Community's JSON schema (lottie-specs, npm,
// with its validator) checks every file the tests export. `.ci/setup` installs both into
// build/node; the tests skip where Chromium or Node.js is missing.
#include "lottie_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>

#include <QPainter>
#include <QProcess>
#include <QTemporaryDir>
#include <QUrl>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {

const QString kNodeModules = QStringLiteral(FINBOOK_SOURCE_DIR "/build/node/node_modules");

QString lottieWeb()
{
    const QString path = kNodeModules + QStringLiteral("/lottie-web/build/player/lottie.min.js");
    return QFileInfo::exists(path) ? path : QString();
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// A page that shows the animation at each of `ticks`, one player per tick, side by side in
// rows of `columns`, each stopped on its frame (lottie-web's SVG renderer, its default).
QString pageFor(const QString &json, QSize size, const std::vector<qint64> &ticks, int columns,
                const QString &file)
{
    QByteArray html =
        "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>"
        "body{margin:0;background:#00ff00}div{position:absolute;width:" +
        QByteArray::number(size.width()) + "px;height:" + QByteArray::number(size.height()) +
        "px}</style><script src=\"" + QUrl::fromLocalFile(lottieWeb()).toEncoded() +
        "\"></script></head><body><script>\nconst data = " + readAll(json) + ";\nconst ticks = [";
    for (std::size_t i = 0; i < ticks.size(); ++i)
        html += (i ? "," : "") + QByteArray::number(ticks[i]);
    html += "];\nticks.forEach((t, i) => {\n"
            "  const d = document.createElement('div');\n"
            "  d.style.left = (i % " +
            QByteArray::number(columns) + ") * " + QByteArray::number(size.width()) +
            " + 'px';\n  d.style.top = Math.floor(i / " + QByteArray::number(columns) + ") * " +
            QByteArray::number(size.height()) +
            " + 'px';\n"
            "  document.body.appendChild(d);\n"
            "  const a = lottie.loadAnimation({container: d, renderer: 'svg', loop: false,\n"
            "    autoplay: false, animationData: JSON.parse(JSON.stringify(data))});\n"
            "  a.goToAndStop(t, true);\n"
            "});\n</script></body></html>\n";
    QFile out(file);
    if (!out.open(QIODevice::WriteOnly) || out.write(html) != html.size())
        return {};
    return file;
}

QImage screenshot(const QString &page, QSize window, const QString &file)
{
    QTemporaryDir profile;
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(chromium(),
            {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
             QStringLiteral("--disable-gpu"), QStringLiteral("--no-first-run"),
             QStringLiteral("--disable-background-networking"),
             QStringLiteral("--disable-component-update"), QStringLiteral("--disable-sync"),
             QStringLiteral("--hide-scrollbars"), QStringLiteral("--force-device-scale-factor=1"),
             QStringLiteral("--allow-file-access-from-files"),
             QStringLiteral("--user-data-dir=") + profile.path(),
             QStringLiteral("--window-size=%1,%2").arg(window.width()).arg(window.height()),
             QStringLiteral("--virtual-time-budget=2000"), QStringLiteral("--screenshot=") + file,
             QUrl::fromLocalFile(page).toString()});
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return {};
    }
    return QImage(file);
}

// Errors and warnings of the published schema's validator for each file, as it prints them.
QJsonArray validate(const QStringList &files, const QString &scriptPath)
{
    const QByteArray script = R"(
const fs = require('fs');
const ajv2020 = require('ajv/dist/2020');
const {LottieValidator, get_schema_path} =
    require('@lottie-animation-community/lottie-specs/src/validator-node.js');
const schema = JSON.parse(fs.readFileSync(get_schema_path(), 'utf8'));
const validator = new LottieValidator(ajv2020.Ajv2020, schema);
const out = process.argv.slice(2).map(f => {
  const problems = validator.validate(fs.readFileSync(f, 'utf8'), true);
  return {file: f, errors: problems.filter(p => p.type == 'error'),
          warnings: problems.filter(p => p.type != 'error')};
});
console.log(JSON.stringify(out));
)";
    QFile f(scriptPath);
    if (!f.open(QIODevice::WriteOnly) || f.write(script) != script.size())
        return {};
    f.close();
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("NODE_PATH"), kNodeModules);
    p.setProcessEnvironment(env);
    p.start(program("node"), QStringList{scriptPath} + files);
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
        qWarning("%s", p.readAllStandardError().constData());
        return {};
    }
    return QJsonDocument::fromJson(p.readAllStandardOutput()).array();
}

} // namespace

class TestExportLottieWeb : public QObject {
    Q_OBJECT
private slots:
    void playsInLottieWeb_data();
    void playsInLottieWeb();
    void validatesAgainstTheSchema();
};

void TestExportLottieWeb::playsInLottieWeb_data()
{
    QTest::addColumn<int>("which");
    QTest::newRow("walk example, holds") << 0;
    QTest::newRow("pressure strokes, transparent") << 1;
    QTest::newRow("nested fills") << 2;
    QTest::newRow("two layers, moving camera") << 3;
    QTest::newRow("shaded fill") << 4;
    QTest::newRow("a cycle played twice") << 5;
    QTest::newRow("pictures, one posed") << 6;
}

void TestExportLottieWeb::playsInLottieWeb()
{
    QFETCH(int, which);
    if (chromium().isEmpty() || lottieWeb().isEmpty())
        QSKIP("Chromium or lottie-web missing (bash .ci/setup installs them)");
    QTemporaryDir dir;
    model::ExportSource source;
    model::ExportOptions o;
    if (which == 0) {
        source = exampleWithHolds();
        o.scale = 0.25;
    } else {
        source.settings = smallPage();
        source.frames = {which == 1   ? pressureStrokes()
                         : which == 4 ? shadedBody()
                                      : nestedFills()};
        if (which == 3)
            source = layeredScene();
        if (which == 5)
            source = cycle(2);
        if (which == 6)
            source = picturesScene();
        o.transparent = which == 1;
    }
    o.format = model::ExportFormat::Lottie;
    o.target = dir.filePath(QStringLiteral("anim.json"));
    QVERIFY(model::exportAnimation(source, o));
    const auto plan = model::planExport(source, o);
    std::vector<qint64> ticks;
    for (qint64 t = 0; t < plan->ticks; ++t)
        ticks.push_back(t);
    const int columns = std::max(1, 1200 / plan->size.width());
    const int rows = int((ticks.size() + std::size_t(columns) - 1) / std::size_t(columns));
    const QString page =
        pageFor(o.target, plan->size, ticks, columns, dir.filePath(QStringLiteral("page.html")));
    QVERIFY(!page.isEmpty());
    const QImage shot =
        screenshot(page, QSize(columns * plan->size.width(), rows * plan->size.height()),
                   dir.filePath(QStringLiteral("shot.png")));
    QVERIFY2(!shot.isNull(), "Chromium made no screenshot");
    double worst = 1.0;
    qint64 worstTick = -1;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const QRect cell(QPoint(int(i % std::size_t(columns)) * plan->size.width(),
                                int(i / std::size_t(columns)) * plan->size.height()),
                         plan->size);
        QImage web = shot.copy(cell).convertToFormat(QImage::Format_ARGB32_Premultiplied);
        QImage ours = finbookFrame(source, *plan, ticks[i]);
        if (plan->transparent) { // the page's green shows through both
            QImage under(plan->size, QImage::Format_ARGB32_Premultiplied);
            under.fill(QColor(0, 255, 0));
            QPainter painter(&under);
            painter.drawImage(0, 0, ours);
            painter.end();
            ours = under;
        }
        const double a = agreement(ours, web);
        if (a < worst) {
            worst = a;
            worstTick = ticks[i];
        }
        if (a < 0.98) {
            ours.save(o.target + QStringLiteral(".tick%1.finbook.png").arg(ticks[i]));
            web.save(o.target + QStringLiteral(".tick%1.web.png").arg(ticks[i]));
        }
    }
    qInfo("lottie-web, %zu ticks: worst tick %lld agrees %.2f %%", ticks.size(), worstTick,
          100 * worst);
    if (worst < 0.98)
        dir.setAutoRemove(false);
    QVERIFY2(worst >= 0.98, qPrintable(dir.path()));
}

void TestExportLottieWeb::validatesAgainstTheSchema()
{
    if (program("node").isEmpty() ||
        !QFileInfo::exists(kNodeModules + QStringLiteral("/@lottie-animation-community")))
        QSKIP("Node.js or lottie-specs missing (bash .ci/setup installs them)");
    QTemporaryDir dir;
    QStringList files;
    const auto save = [&](const model::ExportSource &source, const QString &name,
                          bool transparent) {
        model::ExportOptions o;
        o.format = model::ExportFormat::Lottie;
        o.target = dir.filePath(name);
        o.transparent = transparent;
        o.scale = 0.5;
        if (model::exportAnimation(source, o))
            files << o.target;
    };
    model::ExportSource pen, fills;
    pen.settings = fills.settings = smallPage();
    pen.frames = {pressureStrokes(), pressureStrokes()};
    pen.frames.back().hold = 3;
    fills.frames = {nestedFills()};
    save(exampleWithHolds(), QStringLiteral("walk.json"), false);
    save(pen, QStringLiteral("pen.json"), true);
    save(fills, QStringLiteral("fills.json"), false);
    save(layeredScene(), QStringLiteral("scene.json"), false);
    save(cycle(2), QStringLiteral("cycle.json"), false);
    save(picturesScene(), QStringLiteral("pictures.json"), false);
    QCOMPARE(files.size(), 6);
    const QJsonArray results = validate(files, dir.filePath(QStringLiteral("validate.js")));
    QCOMPARE(results.size(), 6);
    for (const QJsonValue &v : results) {
        const QJsonObject r = v.toObject();
        const QJsonArray errors = r[QStringLiteral("errors")].toArray();
        qInfo("%s: %lld errors, %lld warnings",
              qPrintable(QFileInfo(r[QStringLiteral("file")].toString()).fileName()),
              qint64(errors.size()), qint64(r[QStringLiteral("warnings")].toArray().size()));
        QSet<QString> said; // each kind of warning once
        for (const QJsonValue &w : r[QStringLiteral("warnings")].toArray()) {
            const QString message = w.toObject()[QStringLiteral("message")].toString();
            if (!said.contains(message))
                qInfo("  warning: %s", qPrintable(message));
            said.insert(message);
        }
        QVERIFY2(errors.isEmpty(), QJsonDocument(errors).toJson().left(2000).constData());
    }
}

QTEST_GUILESS_MAIN(TestExportLottieWeb)
#include "tst_export_lottie_web.moc"
