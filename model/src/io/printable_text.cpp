#include <finbook/model/io/printable_text.h>

namespace finbook::model {

namespace {
bool isHidden(char16_t c)
{
    return c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x2028 || c == 0x2029 ||
           (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069) || c == 0x200e ||
           c == 0x200f || c == 0x061c;
}
} // namespace

QString printableText(const QString &text)
{
    bool clean = true;
    for (QChar c : text)
        clean = clean && !isHidden(c.unicode()) && c != QLatin1Char('\\');
    if (clean)
        return text;
    QString out;
    out.reserve(text.size() + 8);
    for (qsizetype i = 0; i < text.size(); ++i) {
        const char16_t c = text[i].unicode();
        if (c == u'\\') {
            const QChar next = i + 1 < text.size() ? text[i + 1] : QChar();
            out += next == QLatin1Char('x') || next == QLatin1Char('u') ? QStringLiteral("\\\\")
                                                                        : QStringLiteral("\\");
        } else if (c <= 0xff && isHidden(c)) {
            out += QStringLiteral("\\x%1").arg(uint(c), 2, 16, QLatin1Char('0'));
        } else if (isHidden(c)) {
            out += QStringLiteral("\\u{%1}").arg(uint(c), 4, 16, QLatin1Char('0'));
        } else {
            out += QChar(c);
        }
    }
    return out;
}

} // namespace finbook::model
