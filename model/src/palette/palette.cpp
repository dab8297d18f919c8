#include "../command_text.h"

#include <finbook/model/document.h>
#include <finbook/model/palette/palette.h>

#include <QCoreApplication>
#include <QList>
#include <QtEndian>

#include <algorithm>

namespace finbook::model {

namespace {

struct PaletteText {
    Q_DECLARE_TR_FUNCTIONS(Palette)
};

QString cleanedName(const QString &name)
{
    QString out = name.simplified(); // no line breaks or tabs: a .gpl line holds it
    if (out.size() > kMaxSwatchNameChars)
        out.truncate(kMaxSwatchNameChars);
    return out;
}

void appendU32(QByteArray &out, quint32 v)
{
    char bytes[4];
    qToLittleEndian<quint32>(v, bytes);
    out.append(bytes, 4);
}

void appendText(QByteArray &out, const QString &text)
{
    const QByteArray utf8 = text.toUtf8();
    appendU32(out, quint32(utf8.size()));
    out.append(utf8);
}

} // namespace

Palette defaultPalette()
{
    Palette p;
    p.name = PaletteText::tr("Finbook");
    p.swatches = {{0xff000000, PaletteText::tr("Black")},  {0xff808080, PaletteText::tr("Grey")},
                  {0xffffffff, PaletteText::tr("White")},  {0xff9040b0, PaletteText::tr("Purple")},
                  {0xff3060d0, PaletteText::tr("Blue")},   {0xffd03030, PaletteText::tr("Red")},
                  {0xfff09020, PaletteText::tr("Orange")}, {0xffe8d020, PaletteText::tr("Yellow")},
                  {0xff30a040, PaletteText::tr("Green")},  {0xff8a5a30, PaletteText::tr("Brown")}};
    return p;
}

Palette sanitizedPalette(Palette palette)
{
    palette.name = cleanedName(palette.name);
    if (palette.swatches.size() > std::size_t(kMaxSwatches))
        palette.swatches.resize(std::size_t(kMaxSwatches));
    for (Swatch &s : palette.swatches) {
        s.color |= 0xff000000u;
        s.name = cleanedName(s.name);
    }
    return palette;
}

Expected<Palette, QString> readGpl(const QByteArray &bytes)
{
    QByteArray text = bytes;
    if (text.startsWith("\xef\xbb\xbf"))
        text.remove(0, 3);
    const QList<QByteArray> lines = text.split('\n');
    if (lines.isEmpty() || lines.front().trimmed() != "GIMP Palette")
        return unexpected(PaletteText::tr("it is not a GIMP palette (its first line is not "
                                          "\"GIMP Palette\")"));
    Palette palette;
    int channels = 3;
    bool swatchesBegun = false;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QString line = QString::fromUtf8(lines[i]).trimmed();
        const int number = int(i) + 1;
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        if (!swatchesBegun) {
            if (line.startsWith(QLatin1String("Name:"), Qt::CaseInsensitive)) {
                palette.name = line.mid(5).trimmed();
                continue;
            }
            if (line.startsWith(QLatin1String("Columns:"), Qt::CaseInsensitive))
                continue;
            if (line.startsWith(QLatin1String("Channels:"), Qt::CaseInsensitive)) {
                const QString kind = line.mid(9).trimmed().toUpper();
                if (kind == QLatin1String("RGBA"))
                    channels = 4;
                else if (kind != QLatin1String("RGB"))
                    return unexpected(PaletteText::tr("line %1: channels \"%2\" are not RGB or "
                                                      "RGBA")
                                          .arg(number)
                                          .arg(kind));
                continue;
            }
        }
        swatchesBegun = true;
        // "R G B [A] name": numbers first, separated by spaces or tabs; the rest is the name.
        int values[4] = {0, 0, 0, 255};
        qsizetype at = 0;
        for (int c = 0; c < channels; ++c) {
            while (at < line.size() && line[at].isSpace())
                ++at;
            const qsizetype start = at;
            while (at < line.size() && !line[at].isSpace())
                ++at;
            bool ok = false;
            const int v = line.mid(start, at - start).toInt(&ok);
            if (!ok || v < 0 || v > 255)
                return unexpected(PaletteText::tr("line %1 is not a colour (%2 numbers from 0 "
                                                  "to 255, then a name)")
                                      .arg(number)
                                      .arg(channels));
            values[c] = v;
        }
        if (int(palette.swatches.size()) >= kMaxSwatches)
            return unexpected(PaletteText::tr("it holds more than %1 colours").arg(kMaxSwatches));
        palette.swatches.push_back({qRgb(values[0], values[1], values[2]), line.mid(at)});
    }
    return sanitizedPalette(std::move(palette));
}

QByteArray writeGpl(const Palette &palette)
{
    QByteArray out = "GIMP Palette\n";
    out += "Name: " + cleanedName(palette.name).toUtf8() + "\n";
    out += "Columns: 5\n#\n";
    for (const Swatch &s : palette.swatches) {
        out += QStringLiteral("%1 %2 %3\t%4\n")
                   .arg(qRed(s.color), 3)
                   .arg(qGreen(s.color), 3)
                   .arg(qBlue(s.color), 3)
                   .arg(cleanedName(s.name))
                   .toUtf8();
    }
    return out;
}

QByteArray paletteSectionPayload(const Palette &palette)
{
    QByteArray out;
    appendText(out, palette.name);
    appendU32(out, quint32(palette.swatches.size()));
    for (const Swatch &s : palette.swatches) {
        appendU32(out, s.color);
        appendText(out, s.name);
    }
    return out;
}

Expected<Palette, QString> readPaletteSection(const QByteArray &payload)
{
    qsizetype at = 0;
    const auto u32 = [&](quint32 *v) {
        if (payload.size() - at < 4)
            return false;
        *v = qFromLittleEndian<quint32>(payload.constData() + at);
        at += 4;
        return true;
    };
    const auto text = [&](QString *s) {
        quint32 n = 0;
        if (!u32(&n) || n > quint32(kMaxSwatchNameChars * 4) || payload.size() - at < qsizetype(n))
            return false;
        *s = QString::fromUtf8(payload.constData() + at, qsizetype(n));
        at += qsizetype(n);
        return true;
    };
    const QString damaged = PaletteText::tr("the palette is damaged");
    Palette palette;
    quint32 count = 0;
    if (!text(&palette.name) || !u32(&count))
        return unexpected(damaged);
    if (count > quint32(kMaxSwatches))
        return unexpected(PaletteText::tr("the palette claims %1 colours").arg(count));
    palette.swatches.reserve(count);
    for (quint32 i = 0; i < count; ++i) {
        Swatch s;
        if (!u32(&s.color) || !text(&s.name))
            return unexpected(damaged);
        palette.swatches.push_back(std::move(s));
    }
    if (at != payload.size())
        return unexpected(damaged);
    return sanitizedPalette(std::move(palette));
}

SetPaletteCommand::SetPaletteCommand(Document *doc, Palette palette, const QString &text)
    : m_doc(doc)
    , m_new(sanitizedPalette(std::move(palette)))
    , m_old(doc->palette())
{
    setText(text);
}

void SetPaletteCommand::redo()
{
    m_doc->setPalette(m_new);
}

void SetPaletteCommand::undo()
{
    m_doc->setPalette(m_old);
}

} // namespace finbook::model
