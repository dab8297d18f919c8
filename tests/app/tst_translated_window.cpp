// The real main window in English, German, French and Japanese: every menu's mnemonics are
// unique in the translations, toolbar buttons show no Japanese "(X)" mnemonic, and the
// Keyboard Shortcuts dialog and the Preferences shortcut editor show each action and shortcut
// in full (translations run longer than English: "Dokumenteinstellungen..." was elided).
#include <finbook/ui/dialogs/preferences_dialog.h>
#include <finbook/ui/dialogs/shortcut_editor.h>
#include <finbook/ui/dialogs/shortcuts_dialog.h>
#include <finbook/ui/window/main_window.h>

#include <QAbstractButton>
#include <QHeaderView>
#include <QLabel>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTranslator>
#include <QtTest>

#include <memory>
#include <vector>

using namespace finbook;

namespace {

const QString kQmDir = QStringLiteral(FINBOOK_BINARY_DIR "/bin/translations");

// Finbook's and Qt's catalogues for `language`, installed for the lifetime of this object
// (Qt's gives the key names in shortcuts, "Strg" and "Maj"); English installs none.
class Language {
public:
    explicit Language(const QString &language)
    {
        if (language == QLatin1String("en"))
            return;
        auto finbook = std::make_unique<QTranslator>();
        m_loaded = finbook->load(kQmDir + QStringLiteral("/finbook_%1.qm").arg(language));
        install(std::move(finbook));
        auto qt = std::make_unique<QTranslator>();
        if (qt->load(QStringLiteral("qtbase_") + language,
                     QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            install(std::move(qt));
    }
    ~Language()
    {
        for (const auto &t : m_translators)
            QCoreApplication::removeTranslator(t.get());
    }
    bool loaded() const { return m_loaded || m_translators.empty(); }

private:
    void install(std::unique_ptr<QTranslator> translator)
    {
        QCoreApplication::installTranslator(translator.get());
        m_translators.push_back(std::move(translator));
    }
    std::vector<std::unique_ptr<QTranslator>> m_translators;
    bool m_loaded = false;
};

// The key a menu text's mnemonic gives ("&Datei" -> d, "ファイル(&F)" -> f), or a null QChar.
QChar mnemonic(const QString &text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (text[i + 1] != QLatin1Char('&'))
            return text[i + 1].toLower();
        ++i;
    }
    return {};
}

// "Menu: 'x' is used by A and B" for every clash among `actions`, recursing into submenus.
void collectClashes(const QString &where, const QList<QAction *> &actions, QStringList &clashes)
{
    QHash<QChar, QString> used;
    for (QAction *a : actions) {
        if (a->isSeparator() || !a->isVisible())
            continue;
        const QChar key = mnemonic(a->text());
        if (!key.isNull()) {
            if (used.contains(key))
                clashes << QStringLiteral("%1: '%2' is used by \"%3\" and \"%4\"")
                               .arg(where, QString(key), used[key], a->text());
            used.insert(key, a->text());
        }
        if (QMenu *sub = a->menu())
            collectClashes(where + QStringLiteral(" > ") + a->text(), sub->actions(), clashes);
    }
}

// Action names in a list are read, not typed: no "&" and no Japanese "(X)" left in them.
QStringList namesWithMnemonics(const QTableWidget *table)
{
    static const QRegularExpression bracketed(QStringLiteral("\\S\\(&?[A-Za-z0-9]\\)"));
    QStringList found;
    for (int r = 0; r < table->rowCount(); ++r) {
        const QString text = table->item(r, 0) ? table->item(r, 0)->text() : QString();
        if (text.contains(QLatin1Char('&')) || text.contains(bracketed))
            found << text;
    }
    return found;
}

// Every cell of `table` as wide as its text needs: the text plus the item view's margins.
QStringList elidedCells(const QTableWidget *table)
{
    const QFontMetrics metrics(table->font());
    const int margins =
        2 * (table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1);
    QStringList elided;
    for (int r = 0; r < table->rowCount(); ++r) {
        for (int c = 0; c < table->columnCount(); ++c) {
            const QTableWidgetItem *item = table->item(r, c);
            if (!item)
                continue;
            const int needed = metrics.horizontalAdvance(item->text()) + margins;
            if (table->columnWidth(c) < needed)
                elided << QStringLiteral("\"%1\" needs %2 px, its column has %3")
                              .arg(item->text(), QString::number(needed),
                                   QString::number(table->columnWidth(c)));
        }
    }
    // Columns past the viewport's right edge are cut off too.
    if (table->horizontalHeader()->length() > table->viewport()->width())
        elided << QStringLiteral("the columns need %1 px, the table shows %2")
                      .arg(table->horizontalHeader()->length())
                      .arg(table->viewport()->width());
    return elided;
}

} // namespace

class TestTranslatedWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void menusHaveUniqueMnemonics_data() { languages(true); }
    void menusHaveUniqueMnemonics();
    void toolbarButtonsShowNoMnemonic_data() { languages(true); }
    void toolbarButtonsShowNoMnemonic();
    void shortcutListShowsEveryTextInFull_data() { languages(true); }
    void shortcutListShowsEveryTextInFull();
    void preferencesShowEveryTextInFull_data() { languages(true); }
    void preferencesShowEveryTextInFull();
    void controlsFitTheirTextAtTheDefaultSize_data() { languages(true); }
    void controlsFitTheirTextAtTheDefaultSize();

private:
    static void languages(bool withEnglish);
    QTemporaryDir m_settings;
};

void TestTranslatedWindow::initTestCase()
{
    // The window reads and writes settings: keep the user's own out of it.
    QVERIFY(m_settings.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    QCoreApplication::setOrganizationName(QStringLiteral("FinbookTests"));
    QCoreApplication::setApplicationName(QStringLiteral("FinbookTests"));
}

void TestTranslatedWindow::languages(bool withEnglish)
{
    QTest::addColumn<QString>("language");
    for (const char *language : {"en", "de", "fr", "ja"}) {
        if (withEnglish || qstrcmp(language, "en") != 0)
            QTest::newRow(language) << QString::fromLatin1(language);
    }
}

void TestTranslatedWindow::menusHaveUniqueMnemonics()
{
    QFETCH(QString, language);
    Language installed(language);
    QVERIFY2(installed.loaded(), qPrintable(language));
    ui::MainWindow window;
    const QList<QAction *> titles = window.menuBar()->actions();
    QVERIFY(titles.size() >= 8);
    if (language != QLatin1String("en"))
        QVERIFY2(titles.first()->text() != QLatin1String("&File"), "the catalogue was not used");
    QStringList clashes;
    collectClashes(QStringLiteral("menu bar"), titles, clashes);
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
}

void TestTranslatedWindow::toolbarButtonsShowNoMnemonic()
{
    QFETCH(QString, language);
    Language installed(language);
    ui::MainWindow window;
    // "保存(S)"; a shortcut in a tooltip, "ペン (B)", has a space before its bracket.
    static const QRegularExpression bracketed(QStringLiteral("\\S\\(&?[A-Za-z0-9]\\)"));
    const QList<QToolButton *> buttons = window.findChildren<QToolButton *>();
    QVERIFY(buttons.size() > 10);
    QStringList shown;
    for (const QToolButton *b : buttons) {
        if (b->text().contains(bracketed) || b->toolTip().contains(bracketed))
            shown << b->text() + QStringLiteral(" / ") + b->toolTip();
    }
    QVERIFY2(shown.isEmpty(), qPrintable(shown.join(QLatin1Char('\n'))));
}

void TestTranslatedWindow::shortcutListShowsEveryTextInFull()
{
    QFETCH(QString, language);
    Language installed(language);
    ui::MainWindow window;
    ui::ShortcutsDialog dialog(window.shortcuts(), &window);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
    QVERIFY(table);
    QCOMPARE(table->rowCount(), dialog.rowCount());
    const QStringList marked = namesWithMnemonics(table);
    QVERIFY2(marked.isEmpty(), qPrintable(marked.join(QLatin1Char('\n'))));
    const QStringList elided = elidedCells(table);
    QVERIFY2(elided.isEmpty(), qPrintable(elided.join(QLatin1Char('\n'))));
}

void TestTranslatedWindow::preferencesShowEveryTextInFull()
{
    QFETCH(QString, language);
    Language installed(language);
    ui::MainWindow window;
    ui::PreferencesDialog dialog(window.preferences(), window.shortcuts(), &window);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    auto *tabs = dialog.findChild<QTabWidget *>();
    QVERIFY(tabs);
    // A tab bar wider than its widget scrolls or elides its tab titles.
    QVERIFY2(tabs->tabBar()->sizeHint().width() <= tabs->width(),
             qPrintable(QStringLiteral("tabs need %1 px, have %2")
                            .arg(tabs->tabBar()->sizeHint().width())
                            .arg(tabs->width())));
    tabs->setCurrentWidget(dialog.shortcutEditor());
    const auto *table = dialog.shortcutEditor()->findChild<QTableWidget *>();
    QVERIFY(table);
    QVERIFY(table->rowCount() > 20);
    const QStringList marked = namesWithMnemonics(table);
    QVERIFY2(marked.isEmpty(), qPrintable(marked.join(QLatin1Char('\n'))));
    // The key column holds editors, not items: it must fit a long shortcut.
    const int keys = table->fontMetrics().horizontalAdvance(
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Right).toString(QKeySequence::NativeText));
    QVERIFY2(table->columnWidth(1) > keys,
             qPrintable(QStringLiteral("key column %1 px").arg(table->columnWidth(1))));
    const QStringList elided = elidedCells(table);
    QVERIFY2(elided.isEmpty(), qPrintable(elided.join(QLatin1Char('\n'))));
}

// Issue 22, item 8: "Move To…" was cut off in every language and the Skeleton panel's hint at
// the default window size. Every button and label the window shows at 1280×840 gets the room
// its text asks for (a menu button also the room of its arrow, which the style draws over the
// text otherwise).
void TestTranslatedWindow::controlsFitTheirTextAtTheDefaultSize()
{
    QFETCH(QString, language);
    Language installed(language);
    ui::MainWindow window;
    window.resize(1280, 840);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCoreApplication::processEvents();
    QStringList cut;
    // The part of a widget its window and the docks and panels around it show.
    const auto visible = [&window](const QWidget *w) {
        QRect r(w->mapTo(&window, QPoint(0, 0)), w->size());
        for (const QWidget *p = w->parentWidget(); p && p != &window; p = p->parentWidget())
            r &= QRect(p->mapTo(&window, QPoint(0, 0)), p->size());
        return r & window.rect();
    };
    const auto shown = [&](const QWidget *w) { return visible(w).size() == w->size(); };
    const auto visibleWidth = [&](const QWidget *w) { return visible(w).width(); };
    const auto describe = [](const QWidget *w, const QString &text, int has, int needs) {
        return QStringLiteral("%1 \"%2\": %3 px of %4")
            .arg(w->objectName(), text)
            .arg(has)
            .arg(needs);
    };
    for (const QAbstractButton *b : window.findChildren<QAbstractButton *>()) {
        if (!b->isVisible() || b->text().isEmpty())
            continue;
        int needs = b->sizeHint().width();
        if (const auto *tool = qobject_cast<const QToolButton *>(b);
            tool && tool->popupMode() == QToolButton::InstantPopup &&
            (tool->toolButtonStyle() != Qt::ToolButtonIconOnly || tool->icon().isNull()) &&
            (tool->menu() || (tool->defaultAction() && tool->defaultAction()->menu())))
            needs += tool->style()->pixelMetric(QStyle::PM_MenuButtonIndicator, nullptr, tool);
        if (b->width() < needs)
            cut << describe(b, b->text(), b->width(), needs);
        else if (!shown(b))
            cut << describe(b, b->text(), visibleWidth(b), b->width());
    }
    for (const QLabel *l : window.findChildren<QLabel *>()) {
        if (!l->isVisible() || l->text().isEmpty() || l->parent() == window.statusBar())
            continue;
        if (!shown(l))
            cut << describe(l, l->text(), visibleWidth(l), l->width());
        else if (l->wordWrap() ? l->height() < l->heightForWidth(l->width())
                               : l->width() < l->sizeHint().width())
            cut << describe(l, l->text(), l->wordWrap() ? l->height() : l->width(),
                            l->wordWrap() ? l->heightForWidth(l->width()) : l->sizeHint().width());
    }
    QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QLatin1Char('\n'))));
}

QTEST_MAIN(TestTranslatedWindow)
#include "tst_translated_window.moc"
