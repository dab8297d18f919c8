// `cmake --install` into a temporary DESTDIR: the tree holds what a desktop needs (executable,
// translations, desktop entry, MIME type, icons, thumbnailer, AppStream metadata, example,
// licence, manual page) and nothing outside the prefix; the installed Finbook runs from there
// and finds its translations relative to itself, also after the tree is moved; the desktop
// files pass their validators (desktop-file-validate, appstreamcli, xmllint, when installed:
// .ci/setup installs them); a renamed .finbook is recognised by its first bytes.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QImage>
#include <QMap>
#include <QMimeDatabase>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kAppId = QStringLiteral("io.github.finbook.Finbook");
const int kIconSizes[] = {16, 22, 24, 32, 48, 64, 128, 256, 512};

struct Run {
    int code = -1;
    QByteArray out, err;
};

Run run(const QString &program, const QStringList &arguments,
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(env);
    process.start(program, arguments);
    Run r;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit)
        return r;
    r.code = process.exitCode();
    r.out = process.readAllStandardOutput();
    r.err = process.readAllStandardError();
    return r;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The keys of one group of a desktop-entry-style file, values as written.
QMap<QString, QString> keyFileGroup(const QString &path, const QString &group)
{
    QMap<QString, QString> keys;
    bool inGroup = false;
    for (const QString &line : QString::fromUtf8(readAll(path)).split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1Char('[')))
            inGroup = line == QLatin1Char('[') + group + QLatin1Char(']');
        else if (inGroup && line.contains(QLatin1Char('=')))
            keys.insert(line.section(QLatin1Char('='), 0, 0), line.section(QLatin1Char('='), 1));
    }
    return keys;
}

} // namespace

class TestInstall : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void renamedFileIsRecognisedByItsBytes();
    void treeHoldsEverything();
    void nothingOutsideThePrefix();
    void iconsHaveTheirSizes();
    void noBuildPathInInstalledFiles();
    void installedFinbookRuns();
    void translationsFoundFromAMovedPrefix();
    void desktopEntry();
    void thumbnailerEntryRuns();
    void validators_data();
    void validators();

private:
    QTemporaryDir m_dir;
    QString m_root;   // the DESTDIR
    QString m_prefix; // DESTDIR/usr
};

void TestInstall::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_root = m_dir.filePath(QStringLiteral("root"));
    m_prefix = m_root + QStringLiteral("/usr");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("DESTDIR"), m_root);
    const Run install = run(QStringLiteral(FINBOOK_CMAKE_COMMAND),
                            {QStringLiteral("--install"), QStringLiteral(FINBOOK_BINARY_DIR),
                             QStringLiteral("--prefix"), QStringLiteral("/usr")},
                            env);
    QVERIFY2(install.code == 0, install.err.constData());
}

// First, before anything else here asks Qt's MIME database (it reads the folders once).
void TestInstall::renamedFileIsRecognisedByItsBytes()
{
    qputenv("XDG_DATA_DIRS", QFile::encodeName(m_prefix + QStringLiteral("/share")));
    qputenv("XDG_DATA_HOME", QFile::encodeName(m_dir.filePath(QStringLiteral("nohome"))));
    const QString renamed = m_dir.filePath(QStringLiteral("renamed.dat"));
    QVERIFY(
        QFile::copy(m_prefix + QStringLiteral("/share/finbook/examples/walk.finbook"), renamed));
    QMimeDatabase db;
    const QMimeType byBytes = db.mimeTypeForFile(renamed, QMimeDatabase::MatchContent);
    QCOMPARE(byBytes.name(), QStringLiteral("application/x-finbook"));
    QCOMPARE(byBytes.iconName(), QStringLiteral("application-x-finbook"));
    QCOMPARE(
        db.mimeTypeForFile(QStringLiteral("walk.finbook"), QMimeDatabase::MatchExtension).name(),
        QStringLiteral("application/x-finbook"));
    const QString png = m_dir.filePath(QStringLiteral("image.finbook"));
    QVERIFY(QImage(4, 4, QImage::Format_RGB32).save(png, "PNG"));
    // The name alone does not make a file a Finbook animation when its bytes say otherwise.
    QVERIFY(db.mimeTypeForFile(png, QMimeDatabase::MatchContent).name() !=
            QStringLiteral("application/x-finbook"));
}

void TestInstall::treeHoldsEverything()
{
    QStringList expected{
        QStringLiteral("bin/finbook"),
        QStringLiteral("share/applications/%1.desktop").arg(kAppId),
        QStringLiteral("share/metainfo/%1.metainfo.xml").arg(kAppId),
        QStringLiteral("share/mime/packages/%1.xml").arg(kAppId),
        QStringLiteral("share/thumbnailers/finbook.thumbnailer"),
        QStringLiteral("share/icons/hicolor/scalable/apps/%1.svg").arg(kAppId),
        QStringLiteral("share/icons/hicolor/scalable/mimetypes/application-x-finbook.svg"),
        QStringLiteral("share/finbook/examples/walk.finbook"),
        QStringLiteral("share/finbook/translations/finbook_de.qm"),
        QStringLiteral("share/finbook/translations/finbook_fr.qm"),
        QStringLiteral("share/finbook/translations/finbook_ja.qm"),
        // English plural forms ("1 frame", "2 frames"), as the source texts have one form only.
        QStringLiteral("share/finbook/translations/finbook_en.qm"),
        QStringLiteral("share/doc/finbook/copyright"),
        QStringLiteral("share/doc/finbook/COPYING"),
        QStringLiteral("share/doc/finbook/changelog.gz"),
        QStringLiteral("share/man/man1/finbook.1.gz"),
    };
    for (int size : kIconSizes) {
        expected << QStringLiteral("share/icons/hicolor/%1x%1/apps/%2.png").arg(size).arg(kAppId)
                 << QStringLiteral("share/icons/hicolor/%1x%1/mimetypes/application-x-finbook.png")
                        .arg(size);
    }
#ifdef FINBOOK_INSTALLED_LIBDIR
    // A shared build (the sanitizer preset) installs its layer libraries beside bin/.
    for (const char *layer : {"geometry", "deform", "model", "ui"})
        expected << QStringLiteral(FINBOOK_INSTALLED_LIBDIR "/libfinbook_%1.so")
                        .arg(QLatin1String(layer));
#endif
    for (const QString &file : expected)
        QVERIFY2(QFileInfo(m_prefix + QLatin1Char('/') + file).isFile(), qPrintable(file));
    QVERIFY(QFileInfo(m_prefix + QStringLiteral("/bin/finbook")).isExecutable());
    QCOMPARE(readAll(m_prefix + QStringLiteral("/share/finbook/examples/walk.finbook")),
             readAll(QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook")));
    // Nothing else: a file added to the install rules is added to this list.
    QStringList installed;
    QDirIterator it(m_prefix, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        installed << QDir(m_prefix).relativeFilePath(it.next());
    installed.sort();
    expected.sort();
    QCOMPARE(installed, expected);
}

void TestInstall::nothingOutsideThePrefix()
{
    QDirIterator it(m_root, QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden);
    QStringList top;
    while (it.hasNext())
        top << QFileInfo(it.next()).fileName();
    QCOMPARE(top, QStringList{QStringLiteral("usr")});
}

void TestInstall::iconsHaveTheirSizes()
{
    for (int size : kIconSizes) {
        for (const QString &icon : {QStringLiteral("apps/%1.png").arg(kAppId),
                                    QStringLiteral("mimetypes/application-x-finbook.png")}) {
            const QImage image(m_prefix + QStringLiteral("/share/icons/hicolor/%1x%1/").arg(size) +
                               icon);
            QCOMPARE(image.size(), QSize(size, size));
            QVERIFY(image.hasAlphaChannel());
            QCOMPARE(image.pixelColor(0, 0).alpha(), 0); // a transparent corner, not a box
            QVERIFY(image.pixelColor(size / 2, size / 2).alpha() > 0);
        }
    }
}

// An installation that names the build folder would break when the build folder goes.
void TestInstall::noBuildPathInInstalledFiles()
{
    QDirIterator it(m_prefix + QStringLiteral("/share"), QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QByteArray bytes = readAll(file);
        QVERIFY2(!bytes.contains(FINBOOK_BINARY_DIR), qPrintable(file));
        QVERIFY2(!bytes.contains(FINBOOK_SOURCE_DIR), qPrintable(file));
    }
}

void TestInstall::installedFinbookRuns()
{
    const QString finbook = m_prefix + QStringLiteral("/bin/finbook");
    const QString example = m_prefix + QStringLiteral("/share/finbook/examples/walk.finbook");
    const Run version = run(finbook, {QStringLiteral("--version")});
    QCOMPARE(version.code, 0);
    QVERIFY(version.out.startsWith("finbook "));
    const Run info = run(finbook, {QStringLiteral("info"), example});
    QCOMPARE(info.code, 0);
    QVERIFY(info.out.contains("\"frames\":"));
    const QString png = m_dir.filePath(QStringLiteral("installed.png"));
    QCOMPARE(run(finbook, {QStringLiteral("thumbnail"), example, png, QStringLiteral("128")}).code,
             0);
    QCOMPARE(QImage(png).width(), 128);
}

// The translations are found relative to the executable: in DESTDIR, and after the whole tree
// is moved to another prefix.
void TestInstall::translationsFoundFromAMovedPrefix()
{
    const Run german =
        run(m_prefix + QStringLiteral("/bin/finbook"),
            {QStringLiteral("--lang"), QStringLiteral("de"), QStringLiteral("--help")});
    QCOMPARE(german.code, 0);
    QVERIFY2(german.out.contains("Daumenkino-Animationseditor"), german.out.constData());

    const QString moved = m_dir.filePath(QStringLiteral("elsewhere/opt/finbook"));
    QVERIFY(QDir().mkpath(QFileInfo(moved).path()));
    QVERIFY(QDir().rename(m_prefix, moved));
    const Run french =
        run(moved + QStringLiteral("/bin/finbook"),
            {QStringLiteral("--lang"), QStringLiteral("fr"), QStringLiteral("--help")});
    QVERIFY(QDir().rename(moved, m_prefix));
    QCOMPARE(french.code, 0);
    QVERIFY2(french.out.contains("folioscope"), french.out.constData());
}

void TestInstall::desktopEntry()
{
    const auto entry =
        keyFileGroup(m_prefix + QStringLiteral("/share/applications/%1.desktop").arg(kAppId),
                     QStringLiteral("Desktop Entry"));
    QCOMPARE(entry.value(QStringLiteral("Exec")), QStringLiteral("finbook %f"));
    QCOMPARE(entry.value(QStringLiteral("Icon")), kAppId);
    QCOMPARE(entry.value(QStringLiteral("GenericName")),
             QStringLiteral("Flipbook Animation Editor"));
    for (const char *lang : {"de", "fr", "ja"}) {
        QVERIFY(!entry.value(QStringLiteral("GenericName[%1]").arg(QLatin1String(lang))).isEmpty());
        QVERIFY(!entry.value(QStringLiteral("Comment[%1]").arg(QLatin1String(lang))).isEmpty());
    }
    QVERIFY(
        entry.value(QStringLiteral("MimeType")).contains(QStringLiteral("application/x-finbook")));
    const QByteArray metainfo =
        readAll(m_prefix + QStringLiteral("/share/metainfo/%1.metainfo.xml").arg(kAppId));
    QVERIFY(metainfo.contains("<launchable type=\"desktop-id\">" + kAppId.toUtf8() +
                              ".desktop</launchable>"));
    QVERIFY(metainfo.contains("<release version=\"" FINBOOK_VERSION "\""));
}

// The thumbnailer entry's Exec line, run as a file manager runs it (%i in, %o out, %s size),
// with the installed bin/ first on PATH.
void TestInstall::thumbnailerEntryRuns()
{
    const auto entry =
        keyFileGroup(m_prefix + QStringLiteral("/share/thumbnailers/finbook.thumbnailer"),
                     QStringLiteral("Thumbnailer Entry"));
    QCOMPARE(entry.value(QStringLiteral("MimeType")), QStringLiteral("application/x-finbook;"));
    QStringList words = entry.value(QStringLiteral("Exec")).split(QLatin1Char(' '));
    QCOMPARE(words.value(0), QStringLiteral("finbook"));
    const QString in = m_prefix + QStringLiteral("/share/finbook/examples/walk.finbook");
    const QString out = m_dir.filePath(QStringLiteral("thumbnailer.png"));
    for (QString &w : words)
        w.replace(QLatin1String("%i"), in)
            .replace(QLatin1String("%o"), out)
            .replace(QLatin1String("%s"), QLatin1String("256"));
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PATH"),
               m_prefix + QStringLiteral("/bin:") + env.value(QStringLiteral("PATH")));
    const QString program =
        QStandardPaths::findExecutable(words.takeFirst(), {m_prefix + QStringLiteral("/bin")});
    QCOMPARE(program, m_prefix + QStringLiteral("/bin/finbook"));
    const Run r = run(program, words, env);
    QCOMPARE(r.code, 0);
    QCOMPARE(QImage(out).width(), 256);
}

void TestInstall::validators_data()
{
    QTest::addColumn<QString>("tool");
    QTest::addColumn<QStringList>("arguments");
    const QString share = m_prefix + QStringLiteral("/share");
    QTest::newRow("desktop-file-validate")
        << QStringLiteral("desktop-file-validate")
        << QStringList{share + QStringLiteral("/applications/%1.desktop").arg(kAppId)};
    QTest::newRow("appstreamcli validate")
        << QStringLiteral("appstreamcli")
        << QStringList{QStringLiteral("validate"), QStringLiteral("--no-net"),
                       share + QStringLiteral("/metainfo/%1.metainfo.xml").arg(kAppId)};
    QTest::newRow("appstreamcli validate-tree")
        << QStringLiteral("appstreamcli")
        << QStringList{QStringLiteral("validate-tree"), QStringLiteral("--no-net"), m_root};
    QTest::newRow("xmllint mime")
        << QStringLiteral("xmllint")
        << QStringList{QStringLiteral("--noout"),
                       share + QStringLiteral("/mime/packages/%1.xml").arg(kAppId)};
    QTest::newRow("xmllint metainfo")
        << QStringLiteral("xmllint")
        << QStringList{QStringLiteral("--noout"),
                       share + QStringLiteral("/metainfo/%1.metainfo.xml").arg(kAppId)};
    // update-mime-database compiles the XML into a copy of the folder (and says what it
    // does not understand).
    QTest::newRow("update-mime-database")
        << QStringLiteral("update-mime-database")
        << QStringList{QStringLiteral("-V"), m_dir.filePath(QStringLiteral("mime"))};
}

void TestInstall::validators()
{
    QFETCH(QString, tool);
    QFETCH(QStringList, arguments);
    const QString program = QStandardPaths::findExecutable(tool);
    if (program.isEmpty())
        QSKIP(qPrintable(tool + QStringLiteral(" is not installed (.ci/setup installs it)")));
    if (tool == QLatin1String("update-mime-database")) {
        const QString packages = m_dir.filePath(QStringLiteral("mime/packages"));
        QVERIFY(QDir().mkpath(packages));
        QFile::remove(packages + QStringLiteral("/finbook.xml"));
        QVERIFY(QFile::copy(m_prefix + QStringLiteral("/share/mime/packages/%1.xml").arg(kAppId),
                            packages + QStringLiteral("/finbook.xml")));
    }
    const Run r = run(program, arguments);
    QVERIFY2(r.code == 0, (r.out + r.err).constData());
    QVERIFY2(!r.err.contains("arning") && !r.out.contains("W: ") && !r.out.contains("E: "),
             (r.out + r.err).constData());
    if (tool == QLatin1String("update-mime-database"))
        QVERIFY(readAll(m_dir.filePath(QStringLiteral("mime/mime.cache")))
                    .contains("application/x-finbook"));
}

QTEST_GUILESS_MAIN(TestInstall)
#include "tst_install.moc"
