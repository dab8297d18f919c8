// Every reader checks each value before it uses it and stops at the first fault, naming its
// line (or cue); nothing is allocated from a count the file declares.
#include <finbook/model/lipsync/lipsync_import.h>
#include <finbook/model/lipsync/mouth_cues.h>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QXmlStreamReader>

#include <cmath>

namespace finbook::model::lipsync {

namespace {

MouthCueImport failure(const QString &error)
{
    return {{}, error};
}

// Cues in order, or the error that there are none.
MouthCueImport success(std::vector<MouthCue> cues)
{
    cues = normalizedCues(std::move(cues));
    if (cues.empty())
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "The file holds no mouth shapes."));
    return {std::move(cues), {}};
}

QByteArrayView withoutBom(const QByteArray &bytes)
{
    const QByteArrayView view(bytes);
    return view.startsWith("\xef\xbb\xbf") ? view.sliced(3) : view;
}

QString tooLargeError()
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "The file is larger than %1 MiB, too large for lip sync "
                                       "timings.")
        .arg(kMaxLipSyncFileBytes / (1024 * 1024));
}

std::optional<QString> sizeError(const QByteArray &bytes)
{
    if (bytes.size() > kMaxLipSyncFileBytes)
        return tooLargeError();
    if (withoutBom(bytes).trimmed().isEmpty())
        return QCoreApplication::translate("finbook::model::lipsync", "The file is empty.");
    return std::nullopt;
}

// A value from the file, cut short so that a message stays one readable sentence.
QString quoted(QByteArrayView text)
{
    constexpr qsizetype kMaxChars = 40;
    return text.size() <= kMaxChars ? QString::fromUtf8(text)
                                    : QString::fromUtf8(text.first(kMaxChars)) + u'…';
}

class Lines {
public:
    explicit Lines(QByteArrayView text)
        : m_text(text)
    {}
    // The next line without its end of line and surrounding blanks, or nothing at the end.
    std::optional<QByteArrayView> next()
    {
        if (m_pos >= m_text.size())
            return std::nullopt;
        qsizetype end = m_text.indexOf('\n', m_pos);
        if (end < 0)
            end = m_text.size();
        const QByteArrayView line = m_text.sliced(m_pos, end - m_pos).trimmed();
        m_pos = end + 1;
        ++m_number;
        return line;
    }
    std::optional<QByteArrayView> nextNonBlank()
    {
        for (auto line = next(); line; line = next()) {
            if (!line->isEmpty())
                return line;
        }
        return std::nullopt;
    }
    int number() const { return m_number; }

private:
    QByteArrayView m_text;
    qsizetype m_pos = 0;
    int m_number = 0;
};

std::vector<QByteArrayView> fields(QByteArrayView line)
{
    std::vector<QByteArrayView> out;
    qsizetype i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const qsizetype start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i > start)
            out.push_back(line.sliced(start, i - start));
    }
    return out;
}

bool startsWithNoCase(QByteArrayView text, QByteArrayView prefix)
{
    return text.size() >= prefix.size() &&
           text.first(prefix.size()).compare(prefix, Qt::CaseInsensitive) == 0;
}

// Seconds from 0 to kMaxCueSeconds; NaN, infinities and words are not.
std::optional<double> secondsFrom(double value)
{
    if (!std::isfinite(value) || value < 0.0 || value > kMaxCueSeconds)
        return std::nullopt;
    return value;
}

std::optional<double> secondsFrom(QByteArrayView text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok ? secondsFrom(value) : std::nullopt;
}

std::optional<qint64> integerFrom(QByteArrayView text, qint64 lowest, qint64 highest)
{
    bool ok = false;
    const qint64 value = text.toLongLong(&ok);
    if (!ok || value < lowest || value > highest)
        return std::nullopt;
    return value;
}

QString badTimeError(int line, QByteArrayView text)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Line %1: \"%2\" is not a time from 0 to %3 seconds.")
        .arg(line)
        .arg(quoted(text))
        .arg(kMaxCueSeconds);
}

QString backwardsError(int line)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Line %1: the time goes backwards.")
        .arg(line);
}

QString endsBeforeStartError(int line)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Line %1: the mouth cue ends before it starts.")
        .arg(line);
}

QString tooManyError()
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "The file holds more than %1 mouth cues.")
        .arg(kMaxMouthCues);
}

QString badShapeError(int line, QByteArrayView name)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Line %1: \"%2\" is not a mouth shape.")
        .arg(line)
        .arg(quoted(name));
}

std::optional<MouthShape> shapeFromLetter(QByteArrayView text)
{
    return text.size() == 1 ? mouthShapeFromLetter(QChar::fromLatin1(text[0])) : std::nullopt;
}

// Preston Blair's names onto Rhubarb's shapes (lipsync_import.h gives the table).
std::optional<MouthShape> prestonBlairShape(QByteArrayView name)
{
    static constexpr std::pair<const char *, MouthShape> kNames[] = {
        {"MBP", MouthShape::A}, {"etc", MouthShape::B}, {"E", MouthShape::C},
        {"AI", MouthShape::D},  {"O", MouthShape::E},   {"U", MouthShape::F},
        {"WQ", MouthShape::F},  {"FV", MouthShape::G},  {"L", MouthShape::H},
        {"rest", MouthShape::X}};
    for (const auto &[text, shape] : kNames) {
        if (name.compare(text, Qt::CaseInsensitive) == 0)
            return shape;
    }
    return std::nullopt;
}

std::optional<double> validFps(double fps)
{
    return std::isfinite(fps) && fps > 0.0 && fps <= kMaxLipSyncFps ? std::optional(fps)
                                                                    : std::nullopt;
}

QString badFpsError(double fps)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "The frame rate %1 is not a number above 0 and up to %2.")
        .arg(fps)
        .arg(kMaxLipSyncFps);
}

QString truncatedError(int line)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "The file ends too early, after line %1.")
        .arg(line);
}

QString badIntegerError(int line, QByteArrayView text, qint64 lowest, qint64 highest)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Line %1: \"%2\" is not a whole number from %3 to %4.")
        .arg(line)
        .arg(quoted(text))
        .arg(lowest)
        .arg(highest);
}

// Papagayo reads its projects field by field, a line each, blank lines included (a voice's
// text may be blank), and so does this reader.
class PapagayoReader {
public:
    explicit PapagayoReader(QByteArrayView text)
        : m_lines(text)
    {}

    MouthCueImport read()
    {
        if (!readHeader())
            return failure(m_error);
        const auto voices = integer(0, kMaxMouthCues);
        if (!voices)
            return failure(m_error);
        for (qint64 voice = 0; voice < *voices; ++voice) {
            if (!readVoice(voice == 0)) // one mouth is animated: the first voice's
                return failure(m_error);
        }
        if (m_cues.empty())
            return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                       "The Papagayo file holds no phonemes."));
        m_cues.insert(m_cues.begin(), MouthCue{0.0, MouthShape::X}); // at rest before speaking
        return success(std::move(m_cues));
    }

private:
    std::optional<QByteArrayView> line()
    {
        const auto next = m_lines.next();
        if (!next)
            m_error = truncatedError(m_lines.number());
        return next;
    }

    std::optional<qint64> integer(qint64 lowest, qint64 highest)
    {
        const auto text = line();
        if (!text)
            return std::nullopt;
        return integerIn(*text, lowest, highest);
    }

    std::optional<qint64> integerIn(QByteArrayView text, qint64 lowest, qint64 highest)
    {
        const auto value = integerFrom(text, lowest, highest);
        if (!value)
            m_error = badIntegerError(m_lines.number(), text, lowest, highest);
        return value;
    }

    bool fail(const QString &error)
    {
        m_error = error;
        return false;
    }

    bool readHeader()
    {
        const auto header = line();
        if (!header)
            return false;
        if (header->compare("lipsync version 1", Qt::CaseInsensitive) != 0)
            return fail(QCoreApplication::translate("finbook::model::lipsync",
                                                    "Line 1: a Papagayo file starts with "
                                                    "\"lipsync version 1\"."));
        const auto soundPath = line(); // the sound is imported on its own
        const auto fpsText = soundPath ? line() : std::nullopt;
        if (!fpsText)
            return false;
        bool ok = false;
        const auto fps = validFps(fpsText->toDouble(&ok));
        if (!ok || !fps)
            return fail(QCoreApplication::translate("finbook::model::lipsync",
                                                    "Line %1: the frame rate \"%2\" is not a "
                                                    "number above 0 and up to %3.")
                            .arg(m_lines.number())
                            .arg(quoted(*fpsText))
                            .arg(kMaxLipSyncFps));
        m_fps = *fps;
        m_lastFrame = qint64(kMaxCueSeconds * m_fps);
        return integer(0, m_lastFrame).has_value(); // the sound's length in frames
    }

    bool readVoice(bool keep)
    {
        if (!line() || !line()) // its name and its text
            return false;
        const auto phrases = integer(0, kMaxMouthCues);
        if (!phrases)
            return false;
        m_previousFrame = 0;
        m_restFrame.reset();
        for (qint64 phrase = 0; phrase < *phrases; ++phrase) {
            // Its text, start and end frames (the words say when they are spoken).
            if (!line() || !integer(0, m_lastFrame) || !integer(0, m_lastFrame))
                return false;
            const auto words = integer(0, kMaxMouthCues);
            if (!words)
                return false;
            for (qint64 word = 0; word < *words; ++word) {
                if (!readWord(keep))
                    return false;
            }
        }
        if (keep && m_restFrame)
            m_cues.push_back({double(*m_restFrame) / m_fps, MouthShape::X});
        return true;
    }

    // "text start end count": the text may hold blanks, the three numbers end the line.
    bool readWord(bool keep)
    {
        const auto text = line();
        if (!text)
            return false;
        const std::vector<QByteArrayView> parts = fields(*text);
        if (parts.size() < 4)
            return fail(QCoreApplication::translate("finbook::model::lipsync",
                                                    "Line %1 is not a word (\"text, start "
                                                    "frame, end frame, phoneme count\").")
                            .arg(m_lines.number()));
        const size_t n = parts.size();
        const auto start = integerIn(parts[n - 3], 0, m_lastFrame);
        const auto end = start ? integerIn(parts[n - 2], *start, m_lastFrame) : std::nullopt;
        const auto count = end ? integerIn(parts[n - 1], 0, kMaxMouthCues) : std::nullopt;
        if (!count)
            return false;
        for (qint64 i = 0; i < *count; ++i) {
            if (!readPhoneme(keep, *end))
                return false;
        }
        if (*count > 0)
            m_restFrame = *end + 1;
        return true;
    }

    bool readPhoneme(bool keep, qint64 wordEnd)
    {
        const auto text = line();
        if (!text)
            return false;
        const std::vector<QByteArrayView> parts = fields(*text);
        if (parts.size() != 2)
            return fail(QCoreApplication::translate("finbook::model::lipsync",
                                                    "Line %1 is not a phoneme (\"frame "
                                                    "name\").")
                            .arg(m_lines.number()));
        const auto frame = integerIn(parts[0], 0, m_lastFrame);
        if (!frame)
            return false;
        if (*frame > wordEnd)
            return fail(QCoreApplication::translate("finbook::model::lipsync",
                                                    "Line %1: the phoneme at frame %2 comes "
                                                    "after its word's end, frame %3.")
                            .arg(m_lines.number())
                            .arg(*frame)
                            .arg(wordEnd));
        const auto shape = prestonBlairShape(parts[1]);
        if (!shape)
            return fail(badShapeError(m_lines.number(), parts[1]));
        if (*frame < m_previousFrame)
            return fail(backwardsError(m_lines.number()));
        m_previousFrame = *frame;
        if (!keep)
            return true;
        // The mouth rests between words, unless the next word starts before the last ends.
        if (m_restFrame && *m_restFrame <= *frame)
            m_cues.push_back({double(*m_restFrame) / m_fps, MouthShape::X});
        m_restFrame.reset();
        if (m_cues.size() >= size_t(kMaxMouthCues))
            return fail(tooManyError());
        m_cues.push_back({double(*frame) / m_fps, *shape});
        return true;
    }

    Lines m_lines;
    QString m_error;
    double m_fps = 24.0;
    qint64 m_lastFrame = 0;            // the frame a day in
    qint64 m_previousFrame = 0;        // of the voice's last phoneme: frames never go back
    std::optional<qint64> m_restFrame; // after the last word, until the next one starts
    std::vector<MouthCue> m_cues;
};

std::optional<double> secondsFrom(QStringView text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok ? secondsFrom(value) : std::nullopt;
}

// Qt's own reason, without its full stop: it ends our sentence.
QString reason(QString text)
{
    while (text.endsWith(u'.'))
        text.chop(1);
    return text;
}

QString damagedXmlError(const QXmlStreamReader &xml)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "The XML is damaged at line %1: %2.")
        .arg(xml.lineNumber())
        .arg(reason(xml.errorString()));
}

// One <mouthCue start="s" end="s">letter</mouthCue>: an error, or nothing when it was read (or
// when the XML itself is damaged, which the caller reports).
std::optional<QString> readXmlCue(QXmlStreamReader &xml, std::vector<MouthCue> &cues)
{
    const int line = int(xml.lineNumber());
    const QXmlStreamAttributes attributes = xml.attributes();
    const QStringView startText = attributes.value(QLatin1StringView("start"));
    const auto start = secondsFrom(startText);
    if (!start)
        return badTimeError(line, startText.toUtf8());
    if (attributes.hasAttribute(QLatin1StringView("end"))) {
        const QStringView endText = attributes.value(QLatin1StringView("end"));
        const auto end = secondsFrom(endText);
        if (!end)
            return badTimeError(line, endText.toUtf8());
        if (*end < *start)
            return endsBeforeStartError(line);
    }
    const QString letter = xml.readElementText().trimmed();
    if (xml.hasError())
        return std::nullopt;
    const auto shape = letter.size() == 1 ? mouthShapeFromLetter(letter[0]) : std::nullopt;
    if (!shape)
        return badShapeError(line, letter.toUtf8());
    if (!cues.empty() && *start < cues.back().start)
        return backwardsError(line);
    if (cues.size() >= size_t(kMaxMouthCues))
        return tooManyError();
    cues.push_back({*start, *shape});
    return std::nullopt;
}

QString badJsonCueError(qsizetype index, const char *key)
{
    return QCoreApplication::translate("finbook::model::lipsync",
                                       "Mouth cue %1: its \"%2\" is not a time from 0 to %3 "
                                       "seconds.")
        .arg(index + 1)
        .arg(QLatin1StringView(key))
        .arg(kMaxCueSeconds);
}

// One {"start": s, "end": s, "value": "X"}: an error, or nothing when it was read.
std::optional<QString> readJsonCue(const QJsonValue &value, qsizetype index,
                                   std::vector<MouthCue> &cues)
{
    const QJsonObject cue = value.toObject();
    const QJsonValue startValue = cue.value(u"start");
    const auto start = startValue.isDouble() ? secondsFrom(startValue.toDouble()) : std::nullopt;
    if (!start)
        return badJsonCueError(index, "start");
    if (cue.contains(u"end")) {
        const QJsonValue endValue = cue.value(u"end");
        const auto end = endValue.isDouble() ? secondsFrom(endValue.toDouble()) : std::nullopt;
        if (!end)
            return badJsonCueError(index, "end");
        if (*end < *start)
            return QCoreApplication::translate("finbook::model::lipsync",
                                               "Mouth cue %1 ends before it starts.")
                .arg(index + 1);
    }
    const QString letter = cue.value(u"value").toString();
    const auto shape = letter.size() == 1 ? mouthShapeFromLetter(letter[0]) : std::nullopt;
    if (!shape)
        return QCoreApplication::translate("finbook::model::lipsync",
                                           "Mouth cue %1: its \"value\" \"%2\" is not a mouth "
                                           "shape.")
            .arg(index + 1)
            .arg(quoted(letter.toUtf8()));
    if (!cues.empty() && *start < cues.back().start)
        return QCoreApplication::translate("finbook::model::lipsync",
                                           "Mouth cue %1: the time goes backwards.")
            .arg(index + 1);
    cues.push_back({*start, *shape});
    return std::nullopt;
}

} // namespace

MouthCueImport parsePapagayo(const QByteArray &bytes)
{
    if (const auto error = sizeError(bytes))
        return failure(*error);
    return PapagayoReader(withoutBom(bytes)).read();
}

MouthCueImport parseRhubarbJson(const QByteArray &bytes)
{
    if (const auto error = sizeError(bytes))
        return failure(*error);
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "The JSON is damaged at character %1: %2.")
                           .arg(parseError.offset)
                           .arg(reason(parseError.errorString())));
    const QJsonValue list = document.object().value(u"mouthCues");
    if (!list.isArray())
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "The JSON has no \"mouthCues\" list: it is "
                                                   "not a Rhubarb Lip Sync result."));
    const QJsonArray array = list.toArray();
    if (array.size() > kMaxMouthCues)
        return failure(tooManyError());
    std::vector<MouthCue> cues;
    cues.reserve(size_t(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        if (const auto error = readJsonCue(array.at(i), i, cues))
            return failure(*error);
    }
    return success(std::move(cues));
}

MouthCueImport parseRhubarbXml(const QByteArray &bytes)
{
    if (const auto error = sizeError(bytes))
        return failure(*error);
    QXmlStreamReader xml(bytes);
    if (!xml.readNextStartElement())
        return failure(damagedXmlError(xml));
    if (xml.name() != u"rhubarbResult")
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "Line %1: the XML's root is <%2>, not "
                                                   "<rhubarbResult>: it is not a Rhubarb Lip "
                                                   "Sync result.")
                           .arg(xml.lineNumber())
                           .arg(quoted(xml.name().toUtf8())));
    std::vector<MouthCue> cues;
    while (xml.readNextStartElement()) {
        if (xml.name() != u"mouthCues") {
            xml.skipCurrentElement();
            continue;
        }
        while (xml.readNextStartElement()) {
            if (xml.name() != u"mouthCue")
                xml.skipCurrentElement();
            else if (const auto error = readXmlCue(xml, cues))
                return failure(*error);
        }
    }
    while (!xml.atEnd()) // a cut or damaged end shows only when it is read
        xml.readNext();
    if (xml.hasError())
        return failure(damagedXmlError(xml));
    return success(std::move(cues));
}

MouthCueImport parseRhubarbTsv(const QByteArray &bytes)
{
    if (const auto error = sizeError(bytes))
        return failure(*error);
    Lines lines(withoutBom(bytes));
    std::vector<MouthCue> cues;
    while (const auto line = lines.nextNonBlank()) {
        const std::vector<QByteArrayView> parts = fields(*line);
        if (parts.size() != 2)
            return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                       "Line %1 is not \"seconds, tab, shape "
                                                       "letter\".")
                               .arg(lines.number()));
        const auto start = secondsFrom(parts[0]);
        if (!start)
            return failure(badTimeError(lines.number(), parts[0]));
        const auto shape = shapeFromLetter(parts[1]);
        if (!shape)
            return failure(badShapeError(lines.number(), parts[1]));
        if (!cues.empty() && *start < cues.back().start)
            return failure(backwardsError(lines.number()));
        if (cues.size() >= size_t(kMaxMouthCues))
            return failure(tooManyError());
        cues.push_back({*start, *shape});
    }
    return success(std::move(cues));
}

MouthCueImport parseMohoSwitch(const QByteArray &bytes, double fps)
{
    if (!validFps(fps))
        return failure(badFpsError(fps));
    if (const auto error = sizeError(bytes))
        return failure(*error);
    Lines lines(withoutBom(bytes));
    const auto header = lines.nextNonBlank();
    if (!header || header->compare("MohoSwitch1", Qt::CaseInsensitive) != 0)
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "Line %1: Moho switch data starts with "
                                                   "\"MohoSwitch1\".")
                           .arg(lines.number()));
    struct Entry {
        qint64 frame;
        QByteArrayView name;
        int line;
    };
    std::vector<Entry> entries;
    bool lettersOnly = true;
    const auto lastFrame = qint64(kMaxCueSeconds * fps) + 1;
    while (const auto line = lines.nextNonBlank()) {
        const std::vector<QByteArrayView> parts = fields(*line);
        if (parts.size() != 2)
            return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                       "Line %1 is not \"frame shape\".")
                               .arg(lines.number()));
        const auto frame = integerFrom(parts[0], 1, lastFrame);
        if (!frame)
            return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                       "Line %1: \"%2\" is not a frame number "
                                                       "from 1 to %3.")
                               .arg(lines.number())
                               .arg(quoted(parts[0]))
                               .arg(lastFrame));
        if (!entries.empty() && *frame < entries.back().frame)
            return failure(backwardsError(lines.number()));
        if (entries.size() >= size_t(kMaxMouthCues))
            return failure(tooManyError());
        const bool letter = shapeFromLetter(parts[1]).has_value();
        if (!letter && !prestonBlairShape(parts[1]))
            return failure(badShapeError(lines.number(), parts[1]));
        lettersOnly = lettersOnly && letter;
        entries.push_back({*frame, parts[1], lines.number()});
    }
    std::vector<MouthCue> cues;
    cues.reserve(entries.size());
    for (const Entry &entry : entries) {
        const auto shape =
            lettersOnly ? shapeFromLetter(entry.name) : prestonBlairShape(entry.name);
        if (!shape)
            return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                       "Line %1: the letter \"%2\" is among "
                                                       "Preston Blair's names; a file uses one "
                                                       "naming or the other.")
                               .arg(entry.line)
                               .arg(quoted(entry.name)));
        cues.push_back({double(entry.frame - 1) / fps, *shape});
    }
    return success(std::move(cues));
}

MouthCueImport parseMouthCues(const QByteArray &bytes, LipSyncFormat format, double fps)
{
    switch (format) {
    case LipSyncFormat::Papagayo:
        return parsePapagayo(bytes);
    case LipSyncFormat::MohoSwitch:
        return parseMohoSwitch(bytes, fps);
    case LipSyncFormat::RhubarbTsv:
        return parseRhubarbTsv(bytes);
    case LipSyncFormat::RhubarbJson:
        return parseRhubarbJson(bytes);
    case LipSyncFormat::RhubarbXml:
        return parseRhubarbXml(bytes);
    }
    return failure(QString());
}

std::optional<LipSyncFormat> sniffLipSyncFormat(const QByteArray &bytes)
{
    QByteArrayView text = withoutBom(bytes);
    while (!text.isEmpty() && QChar::isSpace(uchar(text.front())))
        text = text.sliced(1);
    if (startsWithNoCase(text, "lipsync version"))
        return LipSyncFormat::Papagayo;
    if (startsWithNoCase(text, "MohoSwitch"))
        return LipSyncFormat::MohoSwitch;
    if (text.startsWith('{'))
        return LipSyncFormat::RhubarbJson;
    if (text.startsWith('<'))
        return LipSyncFormat::RhubarbXml;
    const std::optional<QByteArrayView> first = Lines(text).next();
    const std::vector<QByteArrayView> parts = first ? fields(*first) : fields({});
    if (parts.size() == 2 && secondsFrom(parts[0]) && shapeFromLetter(parts[1]))
        return LipSyncFormat::RhubarbTsv;
    return std::nullopt;
}

MouthCueImport importMouthCues(const QString &path, double fps)
{
    QFile file(path);
    const QString name = QFileInfo(path).fileName();
    if (!file.open(QIODevice::ReadOnly))
        return failure(QCoreApplication::translate("finbook::model::lipsync",
                                                   "\"%1\" could not be opened: %2.")
                           .arg(name, file.errorString()));
    if (file.size() > kMaxLipSyncFileBytes)
        return failure(tooLargeError()); // before reading it
    const QByteArray bytes = file.read(kMaxLipSyncFileBytes + 1);
    const QString suffix = QFileInfo(path).suffix().toLower();
    std::optional<LipSyncFormat> format;
    if (suffix == u"pgo")
        format = LipSyncFormat::Papagayo;
    else if (suffix == u"dat")
        format = LipSyncFormat::MohoSwitch;
    else if (suffix == u"tsv")
        format = LipSyncFormat::RhubarbTsv;
    else if (suffix == u"json")
        format = LipSyncFormat::RhubarbJson;
    else if (suffix == u"xml")
        format = LipSyncFormat::RhubarbXml;
    else
        format = sniffLipSyncFormat(bytes);
    if (!format)
        return failure(
            QCoreApplication::translate("finbook::model::lipsync",
                                        "\"%1\" is not lip sync timings that Finbook reads: "
                                        "Papagayo (.pgo), Moho switch data (.dat) or Rhubarb "
                                        "Lip Sync (.tsv, .json, .xml).")
                .arg(name));
    return parseMouthCues(bytes, *format, fps);
}

QString lipSyncFileFilter()
{
    return QCoreApplication::translate("finbook::model::lipsync", "Lip sync timings") +
           QStringLiteral(" (*.pgo *.dat *.tsv *.txt *.json *.xml)");
}

} // namespace finbook::model::lipsync
