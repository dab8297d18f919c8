// finbook-bench lipsync (issue 49): how well the phones recognised in speech key the right mouth
// shapes. Each English sentence (the bundled list, or --sentences FILE, one a line) is spoken by
// espeak-ng, whose phoneme events time the truth; it is recognised without the text (and, with
// --with-text, with it); truth and recognition go through one phone → shape table, and a 24 fps
// frame counts when its recognised shape is the truth's within a frame either way. The loudness
// fallback is scored the same way as the baseline. The "keyed" columns score what the app keys:
// truth and recognition each through the animator's rules (lipsync/mouth_cues.h: closures
// leading the sound, two frames at least, tweens) to a shape per frame. Real-time factor: the
// recogniser's CPU time over the clip's duration.
#include "bench.h"

#include <finbook/model/lipsync/mouth_cues.h>
#include <finbook/model/lipsync/mouth_shape.h>
#include <finbook/model/lipsync/speech_recognizer.h>

#include <QFile>
#include <QHash>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <espeak-ng/speak_lib.h>

using namespace finbook;
using namespace finbook::model::lipsync;

namespace {

constexpr double kFps = 24.0;

// ---- Truth: espeak-ng's phonemes as ARPAbet --------------------------------------------------

// espeak-ng's phoneme mnemonics of its English voices (the en-us ones and British "en"), as the
// ARPAbet phones of CMUdict; a mnemonic of two phones (an r-coloured vowel) is split evenly.
// Mnemonics that time nothing (";", the palatal mark) are left out; pauses are SIL.
const QHash<QByteArray, QByteArray> &espeakToArpabet()
{
    static const QHash<QByteArray, QByteArray> table = {
        {"p", "P"},       {"b", "B"},       {"m", "M"},       {"t", "T"},       {"t#", "T"},
        {"t2", "T"},      {"*", "T"},       {"d", "D"},       {"d#", "D"},      {"k", "K"},
        {"g", "G"},       {"f", "F"},       {"v", "V"},       {"T", "TH"},      {"D", "DH"},
        {"s", "S"},       {"z", "Z"},       {"S", "SH"},      {"Z", "ZH"},      {"tS", "CH"},
        {"dZ", "JH"},     {"h", "HH"},      {"n", "N"},       {"N", "NG"},      {"l", "L"},
        {"@L", "AH L"},   {"r", "R"},       {"r-", "R"},      {"w", "W"},       {"j", "Y"},
        {"?", "T"},       {"n-", "N"},      {"m-", "M"},      {"@", "AH"},      {"@2", "AH"},
        {"@5", "AH"},     {"a#", "AH"},     {"V", "AH"},      {"3", "ER"},      {"3:", "ER"},
        {"I", "IH"},      {"I2", "IH"},     {"I#", "IH"},     {"i", "IY"},      {"i:", "IY"},
        {"E", "EH"},      {"a", "AE"},      {"aa", "AE"},     {"A:", "AA"},     {"0", "AA"},
        {"O:", "AO"},     {"O", "AO"},      {"O2", "AO"},     {"U", "UH"},      {"u:", "UW"},
        {"oU", "OW"},     {"eI", "EY"},     {"aI", "AY"},     {"aU", "AW"},     {"OI", "OY"},
        {"aI3", "AY ER"}, {"aU3", "AW ER"}, {"aI@", "AY ER"}, {"aU@", "AW ER"}, {"i@", "IY R"},
        {"i@3", "IY R"},  {"e@", "EH R"},   {"o@", "AO R"},   {"O@", "AO R"},   {"A@", "AA R"},
        {"U@", "UH R"},   {"_", "SIL"},     {"_:", "SIL"},    {"_!", "SIL"},    {"_^_", "SIL"},
        {";", ""},
    };
    return table;
}

struct Speech {
    SpeechAudio audio;
    std::vector<TimedPhone> truth;
};

struct PhonemeEvent {
    QByteArray name;
    double at = 0.0;
};

// espeak-ng calls back on the synthesising thread; one synthesis at a time.
std::vector<short> *g_samples = nullptr;
std::vector<PhonemeEvent> *g_events = nullptr;

int collect(short *wav, int count, espeak_EVENT *event)
{
    if (wav && count > 0)
        g_samples->insert(g_samples->end(), wav, wav + count);
    for (; event && event->type != espeakEVENT_LIST_TERMINATED; ++event)
        if (event->type == espeakEVENT_PHONEME)
            g_events->push_back({QByteArray(event->id.string, int(strnlen(event->id.string, 8))),
                                 event->audio_position / 1000.0});
    return 0;
}

std::vector<TimedPhone> truthPhones(const std::vector<PhonemeEvent> &events, double duration)
{
    std::vector<TimedPhone> phones;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const double start = events[i].at;
        const double end = i + 1 < events.size() ? events[i + 1].at : duration;
        const auto found = espeakToArpabet().find(events[i].name);
        if (found == espeakToArpabet().end())
            std::fprintf(stderr, "lipsync: espeak phoneme \"%s\" has no ARPAbet; kept as SIL\n",
                         events[i].name.constData());
        const QByteArray arpabet = found == espeakToArpabet().end() ? "SIL" : found.value();
        const QList<QByteArray> parts = arpabet.split(' ');
        if (arpabet.isEmpty() || end <= start) // a mark that times nothing
            continue;
        for (int k = 0; k < parts.size(); ++k)
            phones.push_back({QString::fromLatin1(parts[k]),
                              start + (end - start) * k / double(parts.size()),
                              start + (end - start) * (k + 1) / double(parts.size())});
    }
    return phones;
}

bool initEspeak()
{
    static const int rate =
        espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                          espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
    if (rate > 0)
        espeak_SetSynthCallback(collect);
    return rate > 0;
}

Speech speak(const QString &sentence, const QByteArray &voice, int wordsPerMinute)
{
    Speech speech;
    std::vector<short> samples;
    std::vector<PhonemeEvent> events;
    g_samples = &samples, g_events = &events;
    const QByteArray text = sentence.toUtf8();
    espeak_SetVoiceByName(voice.constData());
    espeak_SetParameter(espeakRATE, wordsPerMinute, 0);
    espeak_Synth(text.constData(), std::size_t(text.size()) + 1, 0, POS_CHARACTER, 0,
                 espeakCHARS_UTF8, nullptr, nullptr);
    espeak_Synchronize();
    g_samples = nullptr, g_events = nullptr;
    const int rate = 22050; // espeak-ng's, for every voice
    speech.audio.sampleRate = rate;
    speech.audio.samples.reserve(samples.size());
    for (short s : samples)
        speech.audio.samples.push_back(float(s) / 32768.0f);
    speech.truth = truthPhones(events, double(samples.size()) / rate);
    return speech;
}

// ---- Scoring ---------------------------------------------------------------------------------

// One table for truth and recognition, so that the score measures the recogniser: Rhubarb Lip
// Sync's chart (A closed M B P, B most consonants and EE, C EH AE AH IH, D AA, E AO ER,
// F UW OW W, G F V, H L, X rest), a diphthong on the shape it opens with.
MouthShape shapeOf(const QString &phone)
{
    static const QHash<QString, MouthShape> table = {
        {"M", MouthShape::A},  {"B", MouthShape::A},  {"P", MouthShape::A},  {"EH", MouthShape::C},
        {"AE", MouthShape::C}, {"AH", MouthShape::C}, {"IH", MouthShape::C}, {"EY", MouthShape::C},
        {"AA", MouthShape::D}, {"AY", MouthShape::D}, {"AW", MouthShape::D}, {"AO", MouthShape::E},
        {"ER", MouthShape::E}, {"OY", MouthShape::E}, {"UW", MouthShape::F}, {"UH", MouthShape::F},
        {"OW", MouthShape::F}, {"W", MouthShape::F},  {"F", MouthShape::G},  {"V", MouthShape::G},
        {"L", MouthShape::H},  {"SIL", MouthShape::X}};
    return table.value(phone, MouthShape::B); // other consonants, IY
}

// The shape at the middle of each frame.
std::vector<MouthShape> frameShapes(const std::vector<TimedPhone> &phones, int frames)
{
    std::vector<MouthShape> shapes(std::size_t(frames), MouthShape::X);
    for (const TimedPhone &p : phones)
        for (int i = std::max(0, int(p.start * kFps - 0.5)); i < frames; ++i) {
            const double t = (i + 0.5) / kFps;
            if (t >= p.end)
                break;
            if (t >= p.start)
                shapes[std::size_t(i)] = shapeOf(p.phone);
        }
    return shapes;
}

std::vector<MouthShape> frameShapes(const std::vector<MouthCue> &cues, int frames)
{
    std::vector<MouthShape> shapes(std::size_t(frames), MouthShape::X);
    std::size_t cue = 0;
    for (int i = 0; i < frames; ++i) {
        const double t = (i + 0.5) / kFps;
        while (cue + 1 < cues.size() && cues[cue + 1].start <= t)
            ++cue;
        if (!cues.empty() && cues[cue].start <= t)
            shapes[std::size_t(i)] = cues[cue].shape;
    }
    return shapes;
}

// The share of frames whose shape is the truth's at that frame or the one either side.
double matchShare(const std::vector<MouthShape> &truth, const std::vector<MouthShape> &got)
{
    int right = 0;
    const int n = int(truth.size());
    for (int i = 0; i < n; ++i)
        for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j)
            if (got[std::size_t(i)] == truth[std::size_t(j)]) {
                ++right;
                break;
            }
    return n > 0 ? 100.0 * right / n : 0.0;
}

struct Scored {
    double match = 0.0; // %
    double rtf = 0.0;
    bool ok = false;
    double keyed = 0.0; // %, through the rules the app keys with
};

// The shapes the app keys for `phones`, a shape per frame.
std::vector<MouthShape> keyedShapes(const std::vector<TimedPhone> &phones, int frames)
{
    return mouthShapesPerFrame(mouthCuesFromPhones(phones, kFps), kFps, frames);
}

Scored recognised(const Speech &speech, const QString &dialogue, int frames)
{
    const double cpuStart = bench::threadCpuMs();
    const auto result = recognizePhones(speech.audio, dialogue, {});
    const double cpuMs = bench::threadCpuMs() - cpuStart;
    const double seconds = double(speech.audio.samples.size()) / speech.audio.sampleRate;
    if (!result) {
        std::fprintf(stderr, "lipsync: %s\n", qPrintable(result.error().message));
        return {};
    }
    return {matchShare(frameShapes(speech.truth, frames), frameShapes(result->phones, frames)),
            cpuMs / 1000.0 / seconds, true,
            matchShare(keyedShapes(speech.truth, frames), keyedShapes(result->phones, frames))};
}

QStringList sentences(const QStringList &args)
{
    const int at = int(args.indexOf(QStringLiteral("--sentences")));
    QFile file(at >= 0 && at + 1 < args.size()
                   ? args[at + 1]
                   : QStringLiteral(FINBOOK_SOURCE_DIR "/tests/bench/lipsync_sentences.txt"));
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    QStringList lines;
    for (const QByteArray &line : file.readAll().split('\n'))
        if (!line.trimmed().isEmpty())
            lines << QString::fromUtf8(line.trimmed());
    return lines;
}

QString option(const QStringList &args, const QString &name, const QString &fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1] : fallback;
}

QByteArray jsonString(const QString &text)
{
    QByteArray out = "\"";
    for (const QChar c : text) {
        if (c == u'"' || c == u'\\')
            out += '\\';
        out += c < u' ' ? QByteArray(" ") : QString(c).toUtf8();
    }
    return out + '"';
}

double worst(const std::vector<double> &v)
{
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

double highest(const std::vector<double> &v)
{
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

int benchLipsync(const QStringList &args)
{
    const QStringList lines = sentences(args);
    const bool withText = args.contains(QStringLiteral("--with-text"));
    const QByteArray voice =
        option(args, QStringLiteral("--voice"), QStringLiteral("en-us")).toUtf8();
    const int wpm = option(args, QStringLiteral("--rate"), QStringLiteral("160")).toInt();
    if (lines.isEmpty() || !initEspeak()) {
        std::fprintf(stderr, "lipsync: no sentences, or espeak-ng did not start\n");
        return 1;
    }
    std::vector<double> plain, texted, loud, rtfPlain, rtfText, keyedPlain, keyedText;
    for (int i = 0; i < lines.size(); ++i) {
        const Speech speech = speak(lines[i], voice, wpm);
        const double seconds = double(speech.audio.samples.size()) / speech.audio.sampleRate;
        const int frames = int(seconds * kFps);
        const std::vector<MouthShape> truth = frameShapes(speech.truth, frames);
        const double loudness =
            matchShare(truth, frameShapes(loudnessCues(speech.audio, kFps), frames));
        const Scored without = recognised(speech, QString(), frames);
        const Scored with = withText ? recognised(speech, lines[i], frames) : Scored{};
        if (!without.ok || (withText && !with.ok))
            return 1;
        loud.push_back(loudness), plain.push_back(without.match), rtfPlain.push_back(without.rtf);
        keyedPlain.push_back(without.keyed);
        if (withText)
            texted.push_back(with.match), rtfText.push_back(with.rtf),
                keyedText.push_back(with.keyed);
        std::printf(
            "{\"bench\":\"lipsync\",\"sentence\":%d,\"text\":%s,\"seconds\":%.2f,"
            "\"frames\":%d,\"match_without_text_pct\":%.1f,\"match_with_text_pct\":%s,"
            "\"match_loudness_pct\":%.1f,\"rtf_without_text\":%.3f,\"rtf_with_text\":%s,"
            "\"keyed_without_text_pct\":%.1f,\"keyed_with_text_pct\":%s}\n",
            i + 1, jsonString(lines[i]).constData(), seconds, frames, without.match,
            withText ? QByteArray::number(with.match, 'f', 1).constData() : "null", loudness,
            without.rtf, withText ? QByteArray::number(with.rtf, 'f', 3).constData() : "null",
            without.keyed, withText ? QByteArray::number(with.keyed, 'f', 1).constData() : "null");
        std::fflush(stdout);
    }
    const auto orNull = [withText](double v, int decimals) {
        return withText ? QByteArray::number(v, 'f', decimals) : QByteArray("null");
    };
    std::printf("{\"bench\":\"lipsync\",\"summary\":true,\"voice\":\"%s\",\"wpm\":%d,"
                "\"sentences\":%d,\"median_match_without_text_pct\":%.1f,"
                "\"worst_match_without_text_pct\":%.1f,\"median_match_with_text_pct\":%s,"
                "\"worst_match_with_text_pct\":%s,\"median_match_loudness_pct\":%.1f,"
                "\"worst_match_loudness_pct\":%.1f,\"median_rtf_without_text\":%.3f,"
                "\"max_rtf_without_text\":%.3f,\"median_rtf_with_text\":%s,"
                "\"max_rtf_with_text\":%s,\"median_keyed_without_text_pct\":%.1f,"
                "\"median_keyed_with_text_pct\":%s}\n",
                voice.constData(), wpm, int(lines.size()), bench::median(plain), worst(plain),
                orNull(bench::median(texted), 1).constData(), orNull(worst(texted), 1).constData(),
                bench::median(loud), worst(loud), bench::median(rtfPlain), highest(rtfPlain),
                orNull(bench::median(rtfText), 3).constData(),
                orNull(highest(rtfText), 3).constData(), bench::median(keyedPlain),
                orNull(bench::median(keyedText), 1).constData());
    return 0;
}

} // namespace

FINBOOK_BENCH("lipsync",
              "[--sentences FILE] [--with-text] [--voice V] [--rate WPM]  espeak-ng speaks each "
              "sentence; % of 24 fps frames whose recognised mouth shape is right (±1 frame) "
              "without the text (and with it), for the loudness fallback, and the real-time factor",
              benchLipsync);
