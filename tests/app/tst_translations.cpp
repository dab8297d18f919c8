// Every catalogue stays complete: each translations/finbook_<language>.ts (German, French and
// Japanese at least) translates every message with the same placeholders and accelerators and
// the language's number of plural forms; the built .qm serves those translations, with the
// language's plural rule, in the contexts the code looks them up in; and every literal handed to
// tr()/translate() in app/, ui/ and model/ is in every catalogue. A new string without a
// translation in any one language fails here, not in front of that language's users.
#include "tst_translations_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QLocale>
#include <QMap>
#include <QScopeGuard>
#include <QTranslator>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {

const QString kTsDir = QStringLiteral(FINBOOK_SOURCE_DIR "/translations");
const QString kQmDir = QStringLiteral(FINBOOK_BINARY_DIR "/bin/translations");
const QStringList kRequiredLanguages{QStringLiteral("de"), QStringLiteral("fr"),
                                     QStringLiteral("ja")};

// Messages below are built with one multi-argument arg(): chained arg() calls would replace the
// "%1"/"%n" inside a quoted source text.

// Which plural form Qt picks for `n` (Qt's rules in qtranslator.cpp/numerus data); -1 for a
// language this test does not know yet: add its rule here when adding its catalogue.
int pluralForm(const QString &language, int n)
{
    if (language == QLatin1String("de"))
        return n == 1 ? 0 : 1;
    if (language == QLatin1String("fr"))
        return n < 2 ? 0 : 1; // zero is singular in French
    if (language == QLatin1String("ja"))
        return 0; // one form for every count
    return -1;
}

int pluralFormCount(const QString &language)
{
    int count = 0;
    for (int n = 0; n < 200; ++n)
        count = std::max(count, pluralForm(language, n) + 1);
    return count;
}

QString tsFile(const QString &language)
{
    return kTsDir + QStringLiteral("/finbook_%1.ts").arg(language);
}

QString qmFile(const QString &language)
{
    return kQmDir + QStringLiteral("/finbook_%1.qm").arg(language);
}

QString describe(const QString &language, const Message &m)
{
    return QStringLiteral("finbook_%1.ts line %2, context %3, source \"%4\"")
        .arg(language)
        .arg(m.line)
        .arg(m.context, m.source);
}

// A mnemonic must be a key every keyboard has: an ASCII letter or digit ('%' for "&%1", the
// recent-file number). Japanese puts it after the text in brackets: "ファイル(&F)".
QString mnemonicProblem(const QString &language, const QString &text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        const QChar key = text[i + 1];
        if (key == QLatin1Char('&')) {
            ++i;
            continue;
        }
        const bool ascii = key.unicode() < 128 && key.isLetterOrNumber();
        if (!ascii && key != QLatin1Char('%'))
            return QStringLiteral("mnemonic '%1' is not on every keyboard").arg(key);
        const bool bracketed = i > 0 && text[i - 1] == QLatin1Char('(') && i + 2 < text.size() &&
                               text[i + 2] == QLatin1Char(')');
        if (language == QLatin1String("ja") && ascii && !bracketed)
            return QStringLiteral("Japanese mnemonics are written \"(&X)\"");
    }
    return {};
}

void addLanguageRows()
{
    QTest::addColumn<QString>("language");
    const QStringList files =
        QDir(kTsDir).entryList({QStringLiteral("finbook_*.ts")}, QDir::Files, QDir::Name);
    for (const QString &file : files) {
        const QString language = file.mid(8, file.size() - 11);
        QTest::newRow(qPrintable(language)) << language;
    }
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyLanguageHasTheSameMessages();
    void catalogueIsComplete_data() { addLanguageRows(); }
    void catalogueIsComplete();
    void translationsKeepPlaceholdersAndAccelerators_data() { addLanguageRows(); }
    void translationsKeepPlaceholdersAndAccelerators();
    void builtCatalogueTranslates_data() { addLanguageRows(); }
    void builtCatalogueTranslates();
    void modelTextsUseTheCatalogue_data() { addLanguageRows(); }
    void modelTextsUseTheCatalogue();
    void everySourceStringIsInTheCatalogue_data() { addLanguageRows(); }
    void everySourceStringIsInTheCatalogue();

private:
    QMap<QString, Catalogue> m_catalogues;
    QList<Call> m_calls;
};

void TestTranslations::initTestCase()
{
    const QStringList files =
        QDir(kTsDir).entryList({QStringLiteral("finbook_*.ts")}, QDir::Files, QDir::Name);
    for (const QString &file : files) {
        const QString language = file.mid(8, file.size() - 11);
        Catalogue catalogue = readCatalogue(tsFile(language));
        QVERIFY2(catalogue.error.isEmpty(), qPrintable(catalogue.error));
        QVERIFY2(catalogue.messages.size() > 100,
                 qPrintable(file + QStringLiteral(" holds suspiciously few messages")));
        // lrelease takes the plural rule from this attribute, not from the file name.
        QCOMPARE(QLocale(catalogue.language).language(), QLocale(language).language());
        QVERIFY2(
            pluralForm(language, 1) >= 0,
            qPrintable(file + QStringLiteral(": add the language's plural rule to this test")));
        m_catalogues.insert(language, catalogue);
    }
    for (const QString &language : kRequiredLanguages)
        QVERIFY2(m_catalogues.contains(language), qPrintable(tsFile(language) + " is missing"));

    for (const char *folder : {"app", "ui", "model"}) {
        QDirIterator it(QStringLiteral(FINBOOK_SOURCE_DIR "/") + QLatin1String(folder),
                        {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext())
            m_calls << translatableLiterals(it.next());
    }
    QVERIFY2(m_calls.size() > 100, "the source scan found suspiciously few tr() calls");
}

// Catalogues drift apart when lupdate is run on one of them only.
void TestTranslations::everyLanguageHasTheSameMessages()
{
    const auto keys = [](const Catalogue &c) {
        QSet<QString> set;
        for (const Message &m : c.messages)
            set.insert(m.context + QChar(0) + m.source + QChar(0) + m.comment);
        return set;
    };
    const QSet<QString> german = keys(m_catalogues.value(QStringLiteral("de")));
    QStringList problems;
    for (auto it = m_catalogues.cbegin(); it != m_catalogues.cend(); ++it) {
        const QSet<QString> own = keys(it.value());
        for (const QString &k : german - own)
            problems << QStringLiteral("finbook_%1.ts lacks \"%2\"")
                            .arg(it.key(), k.section(QChar(0), 1, 1));
        for (const QString &k : own - german)
            problems << QStringLiteral("finbook_%1.ts has \"%2\", finbook_de.ts does not")
                            .arg(it.key(), k.section(QChar(0), 1, 1));
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::catalogueIsComplete()
{
    QFETCH(QString, language);
    const int forms = pluralFormCount(language);
    QStringList problems;
    for (const Message &m : std::as_const(m_catalogues[language].messages)) {
        if (!m.type.isEmpty())
            problems << QStringLiteral("%1: marked %2").arg(describe(language, m), m.type);
        if (m.translations.isEmpty() || m.translations.contains(QString()))
            problems << QStringLiteral("%1: empty translation").arg(describe(language, m));
        if (m.numerus && m.translations.size() != forms)
            problems << QStringLiteral("%1: %2 needs %3 plural form(s), found %4")
                            .arg(describe(language, m), language, QString::number(forms),
                                 QString::number(m.translations.size()));
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::translationsKeepPlaceholdersAndAccelerators()
{
    QFETCH(QString, language);
    QStringList problems;
    for (const Message &m : std::as_const(m_catalogues[language].messages)) {
        for (const QString &t : m.translations) {
            if (t.isEmpty())
                continue; // reported by catalogueIsComplete
            const QString where = describe(language, m);
            if (placeholders(m.source) != placeholders(t))
                problems << QStringLiteral("%1: placeholders differ in \"%2\"").arg(where, t);
            if (accelerators(m.source) != accelerators(t))
                problems << QStringLiteral("%1: '&' accelerators differ in \"%2\"").arg(where, t);
            if (const QString problem = mnemonicProblem(language, t); !problem.isEmpty())
                problems << QStringLiteral("%1: %2 in \"%3\"").arg(where, problem, t);
        }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::builtCatalogueTranslates()
{
    QFETCH(QString, language);
    QTranslator translator;
    QVERIFY2(QFile::exists(qmFile(language)),
             qPrintable(qmFile(language) + QStringLiteral(" is missing: build the "
                                                          "finbook_translations target first")));
    QVERIFY2(translator.load(qmFile(language)), qPrintable(qmFile(language)));
    const QString file = translator.translate("finbook::ui::MainWindow", "&File");
    QVERIFY(!file.isEmpty());
    QVERIFY(file != QLatin1String("&File"));

    // The .qm is built from this very .ts: every message comes back as written, and plural
    // forms are picked by the language's rule (zero is singular in French, Japanese has one).
    QStringList stale;
    for (const Message &m : std::as_const(m_catalogues[language].messages)) {
        const QByteArray context = m.context.toUtf8();
        const QByteArray source = m.source.toUtf8();
        const QByteArray comment = m.comment.toUtf8();
        const char *disambiguation = comment.isEmpty() ? nullptr : comment.constData();
        for (int n : {0, 1, 2, 3, 5, 11, 21, 101}) {
            const QString expected = m.translations.value(m.numerus ? pluralForm(language, n) : 0);
            const QString got = translator.translate(context.constData(), source.constData(),
                                                     disambiguation, m.numerus ? n : -1);
            if (got != expected)
                stale << QStringLiteral("%1: for n = %2 the .qm gives \"%3\", not \"%4\"")
                             .arg(describe(language, m), QString::number(n), got, expected);
            if (!m.numerus)
                break;
        }
    }
    QVERIFY2(stale.isEmpty(), qPrintable(stale.join(QLatin1Char('\n'))));
}

// The contexts the model looks texts up in at run time are the ones lupdate filed them under.
void TestTranslations::modelTextsUseTheCatalogue()
{
    QFETCH(QString, language);
    const Catalogue &catalogue = m_catalogues[language];
    const auto translation = [&](const char *context, const char *source) {
        for (const Message &m : catalogue.messages)
            if (m.context == QLatin1String(context) && m.source == QLatin1String(source))
                return m.translations.value(0);
        return QString();
    };
    QTranslator translator;
    QVERIFY2(translator.load(qmFile(language)), qPrintable(qmFile(language)));
    QVERIFY(QCoreApplication::installTranslator(&translator));
    auto removeTranslator = qScopeGuard([&] { QCoreApplication::removeTranslator(&translator); });

    model::Document doc;
    model::InsertFrameCommand insert(&doc, 0);
    QVERIFY(insert.text() != QLatin1String("Insert Frame"));
    QCOMPARE(insert.text(), translation("Command", "Insert Frame"));

    const auto missing = model::loadFinbook(QStringLiteral("/nonexistent/walk.finbook"));
    QVERIFY(!missing);
    const QString pattern =
        translation("FinbookFile",
                    "Cannot open \"%1\": %2. Check that the file exists and that you may read it.");
    static const QRegularExpression placeholder(QStringLiteral("%[12]"));
    for (const QString &fragment : pattern.split(placeholder, Qt::SkipEmptyParts))
        QVERIFY2(missing.error().message.contains(fragment),
                 qPrintable(missing.error().message + QStringLiteral(" lacks ") + fragment));

    const auto meshed = model::meshObject(model::MeshKey{});
    QVERIFY(!meshed);
    QCOMPARE(meshed.error(), translation("Deformation", "The object has no strokes to deform."));
}

void TestTranslations::everySourceStringIsInTheCatalogue()
{
    QFETCH(QString, language);
    QSet<QString> sources;
    QSet<QPair<QString, QString>> pairs;
    for (const Message &m : std::as_const(m_catalogues[language].messages)) {
        sources.insert(m.source);
        pairs.insert({m.context, m.source});
    }
    QStringList missing;
    for (const Call &c : std::as_const(m_calls)) {
        const bool found =
            c.context.isNull() ? sources.contains(c.source) : pairs.contains({c.context, c.source});
        if (!found)
            missing << QStringLiteral("%1:%2: \"%3\"%4")
                           .arg(c.file)
                           .arg(c.line)
                           .arg(c.source, c.context.isNull()
                                              ? QString()
                                              : QStringLiteral(" in context ") + c.context);
    }
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("not in finbook_%1.ts; run lupdate (see "
                                       "translations/CMakeLists.txt) and translate:\n")
                            .arg(language) +
                        missing.join(QLatin1Char('\n'))));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
