// A file that will not open is explained in an animator's words in the real message box, the
// loader's technical sentence sits under "Show Details", and the backup Finbook keeps beside
// a saved file is named only when it is there.
#include "tst_window_support.h"

#include <finbook/model/finbook_file.h>
#include <finbook/ui/dialogs/file_messages.h>

#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <QtEndian>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {
struct SeenBox {
    QString title, text, details;
    bool detailsButton = false;
};

// Answers the next modal message box with OK and says what it showed.
std::shared_ptr<SeenBox> answerNextMessageBox()
{
    auto seen = std::make_shared<SeenBox>();
    auto *timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, seen] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        seen->title = box->windowTitle();
        seen->text = box->text();
        seen->details = box->detailedText();
        for (QAbstractButton *b : box->buttons())
            seen->detailsButton |= box->buttonRole(b) == QMessageBox::ActionRole;
        box->done(QMessageBox::Ok);
        timer->deleteLater();
    });
    timer->start();
    return seen;
}

QByteArray savedBytes(const model::Document &doc, const QString &path)
{
    if (model::saveFinbook(doc, path))
        return {};
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}
} // namespace

class TestFileMessages : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void cutOffFileSaysSoWithDetails();
    void backupIsNamedOnlyWhenItExists();
    void eachProblemInPlainWords_data();
    void eachProblemInPlainWords();

private:
    // Opens `path` through the window and returns the message box it showed.
    SeenBox open(const QString &path)
    {
        const auto seen = answerNextMessageBox();
        const int strokes = int(m_window->document()->frameAt(0).groups[0].strokes.size());
        const bool opened = m_window->openFile(path);
        [&] {
            QVERIFY(!opened);
            QCOMPARE(int(m_window->document()->frameAt(0).groups[0].strokes.size()), strokes);
        }();
        return *seen;
    }
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
    QTemporaryDir m_dir;
    QByteArray m_good; // a valid .finbook with two strokes
};

void TestFileMessages::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    model::Document *doc = m_window->document();
    resetDocument(*doc, 2);
    addStroke(*doc, doc->frameAt(0).groups[0].id, line({10, 10}, {200, 90}));
    addStroke(*doc, doc->frameAt(1).groups[0].id, line({30, 10}, {220, 90}));
    m_good = savedBytes(*doc, path("good.finbook"));
    QVERIFY(m_good.size() > 64);
    QVERIFY(showActive(*m_window));
}

void TestFileMessages::cutOffFileSaysSoWithDetails()
{
    const QString cut = path("cut.finbook");
    QVERIFY(writeBytes(cut, m_good.left(m_good.size() - 20)));
    const SeenBox box = open(cut);
    QVERIFY2(
        box.text.contains(QStringLiteral("The file is damaged near the end: it looks cut off.")),
        qPrintable(box.text));
    QVERIFY(box.text.contains(QStringLiteral("cut.finbook")));
    // The technical part is there for whoever wants it, and only there.
    QVERIFY(box.detailsButton);
    QVERIFY(!box.details.isEmpty());
    QVERIFY(box.details.contains(QDir::toNativeSeparators(cut)));
    QVERIFY(!box.text.contains(QStringLiteral("byte"), Qt::CaseInsensitive));
    // No backup exists: none is promised.
    QVERIFY(!box.text.contains(QStringLiteral("~")));
    QVERIFY(!box.text.contains(QStringLiteral("backup"), Qt::CaseInsensitive));
}

void TestFileMessages::backupIsNamedOnlyWhenItExists()
{
    // Saving twice keeps the first version as "scene.finbook~"; then the file gets cut off.
    const QString scene = path("scene.finbook");
    QVERIFY(!savedBytes(*m_window->document(), scene).isEmpty());
    const QByteArray second = savedBytes(*m_window->document(), scene);
    QVERIFY(QFileInfo::exists(model::finbookBackupPath(scene)));
    QVERIFY(writeBytes(scene, second.left(second.size() / 2)));
    SeenBox box = open(scene);
    QVERIFY2(box.text.contains(QStringLiteral("\u201cscene.finbook~\u201d")), qPrintable(box.text));
    // The backup opens.
    QVERIFY(m_window->openFile(model::finbookBackupPath(scene)));

    // A file from a newer Finbook is not damaged: its older backup is no answer. (A version
    // far beyond this one, such as 0x7f7f7f7f, is a damaged version word: issue 25.)
    QByteArray newer = second;
    qToLittleEndian<quint32>(model::kFinbookFormatVersion + 1, newer.data() + 8);
    QVERIFY(writeBytes(scene, newer));
    box = open(scene);
    QVERIFY2(box.text.contains(QStringLiteral("newer version")), qPrintable(box.text));
    QVERIFY(!box.text.contains(QStringLiteral("~")));
}

void TestFileMessages::eachProblemInPlainWords_data()
{
    QTest::addColumn<QByteArray>("bytes"); // empty with `what` "missing" or "folder"
    QTest::addColumn<QString>("what");
    QTest::addColumn<QString>("said");
    QTest::newRow("missing") << QByteArray() << "missing"
                             << "not there any more";
    QTest::newRow("folder") << QByteArray() << "folder"
                            << "folder, not an animation";
    QTest::newRow("empty") << QByteArray() << "empty"
                           << "empty";
    QTest::newRow("other kind") << QByteArray("GIF89a, not a drawing") << "bytes"
                                << "not a Finbook animation";
}

void TestFileMessages::eachProblemInPlainWords()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, what);
    QFETCH(QString, said);
    const QString file = m_dir.filePath(what + QStringLiteral(".finbook"));
    if (what == QLatin1String("folder"))
        QVERIFY(QDir().mkpath(file));
    else if (what != QLatin1String("missing"))
        QVERIFY(writeBytes(file, bytes));
    const SeenBox box = open(file);
    QVERIFY2(box.text.contains(said), qPrintable(box.text));
    QVERIFY(box.text.startsWith(QStringLiteral("Finbook cannot open")));
    QVERIFY(!box.details.isEmpty());
    // The same sentences come from FileMessages for code that does not go through a window.
    const auto error = model::loadFinbook(file);
    QVERIFY(!error);
    QCOMPARE(ui::FileMessages::openProblem(file, error.error()).text, box.text);
}

QTEST_MAIN(TestFileMessages)
#include "tst_file_messages.moc"
