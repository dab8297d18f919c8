// Shared by the translation tests: a reader for Qt Linguist .ts catalogues and a small C++
// scanner that finds the string literals handed to tr()/translate() in the sources.
#pragma once

#include <QFile>
#include <QList>
#include <QRegularExpression>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QXmlStreamReader>

namespace finbook::test {

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
    QString language; // the <TS language="..."> attribute, which lrelease takes plural rules from
    QList<Message> messages; // without the vanished/obsolete ones lupdate keeps for translators
    QString error;
};

// Messages lupdate keeps after their source text left the code; lrelease drops them.
inline bool isObsolete(const Message &m)
{
    return m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete");
}

inline Catalogue readCatalogue(const QString &path)
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
        if (name == QLatin1String("TS")) {
            catalogue.language = xml.attributes().value(QLatin1String("language")).toString();
        } else if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            if (!message.source.isNull() && !isObsolete(message))
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
    if (!message.source.isNull() && !isObsolete(message))
        catalogue.messages.append(message);
    if (xml.hasError())
        catalogue.error =
            QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return catalogue;
}

// %1..%99, %L1, %n and %Ln, as QString::arg and tr(..., n) replace them.
inline QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%L?(?:[1-9][0-9]?|n)"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured());
    return found;
}

// Mnemonic markers: a single '&'; "&&" is a literal ampersand.
inline qsizetype accelerators(QString text)
{
    text.remove(QStringLiteral("&&"));
    return text.count(QLatin1Char('&'));
}

// --- a small C++ scanner: enough to find the string literals handed to tr() -----------------

// The text with comments replaced by spaces, so commented-out calls are not scanned.
inline QString withoutComments(const QString &code)
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
inline QString readLiteral(const QString &code, qsizetype &pos)
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

inline QList<Call> translatableLiterals(const QString &path)
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

} // namespace finbook::test
