// The window's side of "nothing lost": Open Anyway for a damaged file, the recovery prompt
// and restoring a copy as an unsaved document, the autosave preference.
#include "tst_tools_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/recovery/autosaver.h>
#include <finbook/ui/recovery/recovery_dialog.h>
#include <finbook/ui/window/main_window.h>

#include <QDir>
#include <QFile>
#include <QListWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace finbook;

namespace {
class ScriptedWindow : public ui::MainWindow {
public:
    bool openAnyway = false;
    QString askedAbout;
    QStringList errors;
    std::vector<model::RecoveryCopy> offered;
    RecoveryChoice answer{ui::RecoveryDialog::Action::Later, 0};

protected:
    bool askOpenAnyway(const QString &message) override
    {
        askedAbout = message;
        return openAnyway;
    }
    void reportError(const QString &, const QString &message) override { errors << message; }
    QMessageBox::StandardButton askToSave() override { return QMessageBox::Discard; }
    RecoveryChoice askRecovery(const std::vector<model::RecoveryCopy> &copies) override
    {
        offered = copies;
        return answer;
    }
};

QByteArray damagedExample()
{
    QFile f(QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook"));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QByteArray bytes = f.readAll();
    bytes[bytes.size() * 3 / 4] = char(bytes[bytes.size() * 3 / 4] ^ 0x20);
    return bytes;
}
} // namespace

class TestRecoveryUi : public QObject {
    Q_OBJECT
private slots:
    void init();
    void damagedFileAsksAndOpensAnyway();
    void declinedOpenAnywayKeepsTheDocument();
    void recoveryIsOfferedAndRestored();
    void autosavePreferenceSetsTheInterval();
    void dialogDescribesEachCopy();

private:
    test::IsolatedSettings m_settings; // preferences written here, not in the user's
    QTemporaryDir m_dir;
};

void TestRecoveryUi::init()
{
    qputenv("FINBOOK_RECOVERY_DIR", QFile::encodeName(m_dir.filePath(QStringLiteral("recovery"))));
}

void TestRecoveryUi::damagedFileAsksAndOpensAnyway()
{
    const QString path = m_dir.filePath(QStringLiteral("damaged.finbook"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(damagedExample());
    f.close();
    ScriptedWindow window;
    window.openAnyway = true;
    QVERIFY(window.openFile(path));
    QVERIFY2(window.askedAbout.contains(QLatin1String("damaged")), qPrintable(window.askedAbout));
    QVERIFY(window.errors.isEmpty());
    QVERIFY(window.document()->frameCount() > 0);
    QVERIFY(window.filePath().isEmpty());                // a new document: Save asks where
    QVERIFY(!window.document()->undoStack()->isClean()); // unsaved
    QCOMPARE(QFile(path).size(), qint64(damagedExample().size())); // the file is untouched
}

void TestRecoveryUi::declinedOpenAnywayKeepsTheDocument()
{
    const QString path = m_dir.filePath(QStringLiteral("damaged2.finbook"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(damagedExample());
    f.close();
    ScriptedWindow window;
    const QByteArray before = model::serializeFinbook(*window.document());
    QVERIFY(!window.openFile(path));
    QVERIFY(!window.askedAbout.isEmpty());
    QCOMPARE(model::serializeFinbook(*window.document()), before);
    // A file that is not a .finbook at all is reported, not offered.
    const QString text = m_dir.filePath(QStringLiteral("notes.finbook"));
    QFile t(text);
    QVERIFY(t.open(QIODevice::WriteOnly));
    t.write("hello");
    t.close();
    window.askedAbout.clear();
    QVERIFY(!window.openFile(text));
    QVERIFY(window.askedAbout.isEmpty());
    QCOMPARE(window.errors.size(), 1);
}

void TestRecoveryUi::recoveryIsOfferedAndRestored()
{
    QByteArray autosaved;
    {
        ScriptedWindow crashed;
        model::Document *doc = crashed.document();
        doc->undoStack()->push(new model::InsertFrameCommand(doc, 1));
        doc->undoStack()->push(new model::InsertFrameCommand(doc, 2));
        crashed.autosaver()->autosaveNow();
        crashed.autosaver()->waitForIdle();
        autosaved = model::serializeFinbook(*doc);
    } // destroyed with unsaved changes, as a crash would leave it: the copy stays
    ScriptedWindow next;
    next.answer = {ui::RecoveryDialog::Action::Restore, 0};
    next.offerRecovery();
    QCOMPARE(next.offered.size(), std::size_t(1));
    QCOMPARE(next.offered[0].info.frames, 3);
    QCOMPARE(model::serializeFinbook(*next.document()), autosaved);
    QVERIFY(!next.document()->undoStack()->isClean());
    QVERIFY(next.windowTitle().contains(QLatin1String("Untitled")));
    // The copy is now this window's: another Finbook would not be offered it.
    next.autosaver()->waitForIdle();
    QVERIFY(QFile::exists(next.autosaver()->copyPath()));
    ScriptedWindow third;
    third.offerRecovery();
    QVERIFY(third.offered.empty());
}

void TestRecoveryUi::autosavePreferenceSetsTheInterval()
{
    qunsetenv("FINBOOK_AUTOSAVE_MS");
    ScriptedWindow window;
    QCOMPARE(window.preferences().autosaveMinutes, 2); // the default
    ui::Preferences p = window.preferences();
    p.autosaveMinutes = 7;
    window.setPreferences(p);
    QCOMPARE(window.autosaver()->interval(), 7 * 60 * 1000);
    p.autosaveMinutes = 0;
    window.setPreferences(p);
    QCOMPARE(window.autosaver()->interval(), 0);
    ScriptedWindow later; // the preference is kept
    QCOMPARE(later.autosaver()->interval(), 0);
    p.autosaveMinutes = 2;
    window.setPreferences(p);
}

void TestRecoveryUi::dialogDescribesEachCopy()
{
    model::RecoveryCopy a, b;
    a.info = {QStringLiteral("walk.finbook"), QStringLiteral("/x/walk.finbook"),
              QDateTime::currentDateTimeUtc(), 12};
    b.info = {QString(), QString(), QDateTime::currentDateTimeUtc(), 1};
    b.thumbnail = QImage(16, 9, QImage::Format_ARGB32);
    ui::RecoveryDialog dialog({a, b});
    auto *list = dialog.findChild<QListWidget *>();
    QVERIFY(list);
    QCOMPARE(list->count(), 2);
    QVERIFY(list->item(0)->text().startsWith(QLatin1String("walk.finbook")));
    QVERIFY(list->item(0)->text().contains(QLatin1String("12 frame")));
    QVERIFY(list->item(1)->text().startsWith(QLatin1String("Untitled")));
    QVERIFY(list->item(1)->text().contains(QLatin1String("1 frame")));
    QVERIFY(!list->item(1)->icon().isNull());
    QCOMPARE(dialog.chosen(), 0);
}

QTEST_MAIN(TestRecoveryUi)
#include "tst_recovery_ui.moc"
