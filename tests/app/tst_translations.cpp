// The German catalogue stays complete: every message in finbook_de.ts is translated with the
// same placeholders and accelerators, the built .qm serves those translations in the contexts
// the code looks them up in, and every literal handed to tr()/translate() in app/, ui/ and
// model/ is in the catalogue, so a new string without a translation fails here, not in front
// of a German user.
#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>

#include <QCoreApplication>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSet>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

using namespace finbook;

namespace {

const QString kTsFile = QStringLiteral(FINBOOK_SOURCE_DIR "/translations/finbook_de.ts");
const QString kQmFile = QStringLiteral(FINBOOK_BINARY_DIR "/bin/translations/finbook_de.qm");
const QString kQmMissing = kQmFile + QStringLiteral(" is missing: build the finbook_translations "
                                                    "target (this test depends on it) first");

struct Message {
    QString context;
    QString source;
    QString comment;
    QString type; // the <translation> type attribute: empty when finished
    bool numerus = false;
    QStringList translations; // one entry, or one per numerus form
    qint64 line = 0;
};

struct Catalogue {
    QList<Message> messages;
    QString error;
};

Catalogue readCatalogue(const QString &path)
{
    Catalogue catalogue;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        catalogue.error = QStringLiteral("cannot open %1: %2").arg(path, file.errorString());
        return catalogue;
    }
    QXmlStreamReader xml(&file);
    QString context;
    Message message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            if (!message.source.isNull())
                catalogue.messages.append(message);
            message = Message{};
            message.context = context;
            message.numerus =
                xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            message.line = xml.lineNumber();
        } else if (name == QLatin1String("source")) {
            message.source = xml.readElementText();
        } else if (name == QLatin1String("comment")) {
            message.comment = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            message.type = xml.attributes().value(QLatin1String("type")).toString();
            if (!message.numerus)
                message.translations.append(xml.readElementText());
        } else if (name == QLatin1String("numerusform")) {
            message.translations.append(xml.readElementText());
        }
    }
    if (!message.source.isNull())
        catalogue.messages.append(message);
    if (xml.hasError())
        catalogue.error =
            QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return catalogue;
}

// %1..%99, %L1, %n and %Ln, as QString::arg and tr(..., n) replace them.
QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%L?(?:[1-9][0-9]?|n)"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured());
    return found;
}

// Mnemonic markers: a single '&'; "&&" is a literal ampersand.
qsizetype accelerators(QString text)
{
    text.remove(QStringLiteral("&&"));
    return text.count(QLatin1Char('&'));
}

QString describe(const Message &m)
{
    return QStringLiteral("%1 line %2, context %3, source \"%4\"")
        .arg(QFileInfo(kTsFile).fileName())
        .arg(m.line)
        .arg(m.context, m.source);
}

// --- a small C++ scanner: enough to find the string literals handed to tr() -----------------

// The text with comments replaced by spaces, so commented-out calls are not scanned.
QString withoutComments(const QString &code)
{
    QString out = code;
    for (qsizetype i = 0; i < out.size(); ++i) {
        const QChar c = out[i];
        if (c == QLatin1Char('"') || c == QLatin1Char('\'')) {
            for (++i; i < out.size() && out[i] != c; ++i) {
                if (out[i] == QLatin1Char('\\'))
                    ++i;
            }
        } else if (out.mid(i, 2) == QLatin1String("//")) {
            for (; i < out.size() && out[i] != QLatin1Char('\n'); ++i)
                out[i] = QLatin1Char(' ');
        } else if (out.mid(i, 2) == QLatin1String("/*")) {
            const qsizetype end = out.indexOf(QLatin1String("*/"), i + 2);
            const qsizetype stop = end < 0 ? out.size() : end + 2;
            for (; i < stop; ++i) {
                if (out[i] != QLatin1Char('\n'))
                    out[i] = QLatin1Char(' ');
            }
            --i;
        }
    }
    return out;
}

// Reads one or more adjacent C string literals ("a" "b") starting at `pos` (whitespace
// allowed before each). Returns a null string when `pos` does not start a plain literal.
QString readLiteral(const QString &code, qsizetype &pos)
{
    QString value;
    bool any = false;
    for (;;) {
        qsizetype i = pos;
        while (i < code.size() && code[i].isSpace())
            ++i;
        if (i >= code.size() || code[i] != QLatin1Char('"'))
            break;
        for (++i; i < code.size() && code[i] != QLatin1Char('"'); ++i) {
            if (code[i] != QLatin1Char('\\')) {
                value += code[i];
                continue;
            }
            const QChar e = code[++i];
            if (e == QLatin1Char('n'))
                value += QLatin1Char('\n');
            else if (e == QLatin1Char('t'))
                value += QLatin1Char('\t');
            else if (e == QLatin1Char('u')) {
                value += QChar(code.mid(i + 1, 4).toUShort(nullptr, 16));
                i += 4;
            } else
                value += e;
        }
        pos = i + 1;
        any = true;
    }
    return any ? value : QString();
}

struct Call {
    QString file;
    int line = 0;
    QString context; // known only for translate() and QT_TRANSLATE_NOOP()
    QString source;
};

QList<Call> translatableLiterals(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QString code = withoutComments(QString::fromUtf8(file.readAll()));
    // tr(, X::tr(, tr<Wrapper>( and the no-op markers take the text first; translate() and
    // QT_TRANSLATE_NOOP() take a context first. A wrapper lupdate does not know files no
    // string, which is exactly what the catalogue check below then reports.
    static const QRegularExpression call(
        QStringLiteral("(?<![A-Za-z0-9_])(tr[A-Z][A-Za-z0-9_]*|tr|QT_TR_NOOP|QT_TR_N_NOOP|"
                       "translate|QT_TRANSLATE_NOOP|QT_TRANSLATE_N_NOOP)\\s*\\("));
    QList<Call> calls;
    for (auto it = call.globalMatch(code); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const QString function = m.captured(1);
        qsizetype pos = m.capturedEnd();
        Call c;
        c.file = path;
        c.line = int(code.left(m.capturedStart()).count(QLatin1Char('\n'))) + 1;
        if (function.contains(QLatin1String("TRANSLATE")) ||
            function == QLatin1String("translate")) {
            c.context = readLiteral(code, pos);
            if (c.context.isNull())
                continue; // QTransform::translate(dx, dy) and friends
            while (pos < code.size() && (code[pos].isSpace() || code[pos] == QLatin1Char(',')))
                ++pos;
        }
        c.source = readLiteral(code, pos);
        if (!c.source.isNull())
            calls.append(c);
    }
    return calls;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void catalogueIsComplete();
    void translationsKeepPlaceholdersAndAccelerators();
    void builtCatalogueTranslates();
    void modelTextsUseTheCatalogue();
    void everySourceStringIsInTheCatalogue();

private:
    Catalogue m_catalogue;
};

void TestTranslations::initTestCase()
{
    m_catalogue = readCatalogue(kTsFile);
    QVERIFY2(m_catalogue.error.isEmpty(), qPrintable(m_catalogue.error));
    QVERIFY2(m_catalogue.messages.size() > 100, "finbook_de.ts holds suspiciously few messages");
}

void TestTranslations::catalogueIsComplete()
{
    QStringList problems;
    for (const Message &m : std::as_const(m_catalogue.messages)) {
        if (!m.type.isEmpty())
            problems << QStringLiteral("%1: marked %2").arg(describe(m), m.type);
        if (m.translations.isEmpty() || m.translations.contains(QString()))
            problems << QStringLiteral("%1: empty translation").arg(describe(m));
        if (m.numerus && m.translations.size() != 2)
            problems << QStringLiteral("%1: German needs 2 plural forms, found %2")
                            .arg(describe(m))
                            .arg(m.translations.size());
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::translationsKeepPlaceholdersAndAccelerators()
{
    QStringList problems;
    for (const Message &m : std::as_const(m_catalogue.messages)) {
        for (const QString &t : m.translations) {
            if (t.isEmpty())
                continue; // reported by catalogueIsComplete
            if (placeholders(m.source) != placeholders(t))
                problems << QStringLiteral("%1: placeholders differ in \"%2\"").arg(describe(m), t);
            if (accelerators(m.source) != accelerators(t))
                problems
                    << QStringLiteral("%1: '&' accelerators differ in \"%2\"").arg(describe(m), t);
        }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::builtCatalogueTranslates()
{
    QTranslator translator;
    if (!QFile::exists(kQmFile))
        QFAIL(qPrintable(kQmMissing));
    QVERIFY2(translator.load(kQmFile), qPrintable(kQmFile));

    const QString file = translator.translate("finbook::ui::MainWindow", "&File");
    QVERIFY(!file.isEmpty());
    QVERIFY(file != QLatin1String("&File"));
    QCOMPARE(file, QStringLiteral("&Datei"));
    QCOMPARE(translator.translate("ObjectListModel", "%1: %n stroke(s)", nullptr, 1),
             QStringLiteral("%1: %n Strich"));
    QCOMPARE(translator.translate("ObjectListModel", "%1: %n stroke(s)", nullptr, 3),
             QStringLiteral("%1: %n Striche"));

    // The .qm is built from this very .ts: every singular message comes back as written.
    QStringList stale;
    for (const Message &m : std::as_const(m_catalogue.messages)) {
        if (m.numerus)
            continue;
        const QByteArray context = m.context.toUtf8();
        const QByteArray source = m.source.toUtf8();
        const QByteArray comment = m.comment.toUtf8();
        const QString got = translator.translate(context.constData(), source.constData(),
                                                 comment.isEmpty() ? nullptr : comment.constData());
        if (got != m.translations.value(0))
            stale << QStringLiteral("%1: the .qm gives \"%2\"").arg(describe(m), got);
    }
    QVERIFY2(stale.isEmpty(), qPrintable(stale.join(QLatin1Char('\n'))));
}

// The contexts the model looks texts up in at run time are the ones lupdate filed them under.
void TestTranslations::modelTextsUseTheCatalogue()
{
    if (!QFile::exists(kQmFile))
        QFAIL(qPrintable(kQmMissing));
    QTranslator translator;
    QVERIFY(translator.load(kQmFile));
    QVERIFY(QCoreApplication::installTranslator(&translator));
    auto removeTranslator = qScopeGuard([&] { QCoreApplication::removeTranslator(&translator); });

    model::Document doc;
    model::InsertFrameCommand insert(&doc, 0);
    QCOMPARE(insert.text(), QStringLiteral("Einzelbild einfügen"));

    const auto missing = model::loadFinbook(QStringLiteral("/nonexistent/walk.finbook"));
    QVERIFY(!missing);
    QVERIFY2(missing.error().message.contains(QStringLiteral("kann nicht geöffnet werden")),
             qPrintable(missing.error().message));

    const auto meshed = model::meshObject(model::MeshKey{});
    QVERIFY(!meshed);
    QCOMPARE(meshed.error(), QStringLiteral("Das Objekt hat keine Striche, die sich verformen "
                                            "ließen."));
}

void TestTranslations::everySourceStringIsInTheCatalogue()
{
    QSet<QString> sources;
    QSet<QPair<QString, QString>> pairs;
    for (const Message &m : std::as_const(m_catalogue.messages)) {
        sources.insert(m.source);
        pairs.insert({m.context, m.source});
    }
    QStringList missing;
    int scanned = 0;
    for (const char *folder : {"app", "ui", "model"}) {
        QDirIterator it(QStringLiteral(FINBOOK_SOURCE_DIR "/") + QLatin1String(folder),
                        {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            for (const Call &c : translatableLiterals(it.next())) {
                ++scanned;
                const bool found = c.context.isNull() ? sources.contains(c.source)
                                                      : pairs.contains({c.context, c.source});
                if (!found)
                    missing << QStringLiteral("%1:%2: \"%3\"%4")
                                   .arg(c.file)
                                   .arg(c.line)
                                   .arg(c.source, c.context.isNull()
                                                      ? QString()
                                                      : QStringLiteral(" in context ") + c.context);
            }
        }
    }
    QVERIFY2(scanned > 100, "the source scan found suspiciously few tr() calls");
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("not in finbook_de.ts; run lupdate (see README) and "
                                       "translate:\n") +
                        missing.join(QLatin1Char('\n'))));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
