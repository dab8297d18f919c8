// Recognition runs PocketSphinx 5prealpha through its public C API (pocketsphinx.h and
// sphinxbase): one decoder per call, the clip's cepstra computed once, the search fed block by
// block so that it reports progress and can stop.
#include <finbook/model/lipsync/speech_recognizer.h>

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <pocketsphinx.h>
#include <sphinxbase/cmn.h>
#include <sphinxbase/err.h>
#include <sphinxbase/fe.h>
#include <sphinxbase/feat.h>
#include <sphinxbase/fsg_model.h>
#include <sphinxbase/glist.h>

#ifndef FINBOOK_POCKETSPHINX_MODELDIR // pkg-config --variable=modeldir pocketsphinx
#define FINBOOK_POCKETSPHINX_MODELDIR "/usr/share/pocketsphinx/model"
#endif

namespace finbook::model::lipsync {
namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("finbook::model::lipsync", text);
}

Unexpected<SpeechError> failure(SpeechErrorKind kind, const QString &message)
{
    return unexpected(SpeechError{kind, message});
}

// PocketSphinx logs through one process-wide logger. Its chatter is dropped; its errors are kept
// per thread, so that a failure's message names the cause on the thread that failed.
thread_local QString t_engineError;

void engineLog(void *, err_lvl_t level, const char *format, ...)
{
    if (level < ERR_ERROR)
        return;
    char text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    // "ERROR: "fsg_search.c", line 940: Final result ..." → "Final result ..."
    static const QRegularExpression kSource(QStringLiteral("^.*line \\d+: "));
    t_engineError = QString::fromUtf8(text).remove(kSource).trimmed();
}

void routeEngineLog()
{
    static std::once_flag once;
    std::call_once(once, [] {
        err_set_logfp(nullptr);
        err_set_callback(engineLog, nullptr);
    });
}

// ---- Audio ---------------------------------------------------------------------------------

// Zero crossings of the resampling sinc on each side: with a Blackman window, more than 75 dB
// of stop band.
constexpr int kSincZeros = 16;
constexpr double kPassBand = 0.9; // share of the lower Nyquist frequency kept

double blackman(double x) // x in [-1, 1]
{
    const double a = std::numbers::pi * (x + 1.0);
    return 0.42 - 0.5 * std::cos(a) + 0.08 * std::cos(2.0 * a);
}

// Shortest clip worth recognising, and the loudness (RMS, full scale 1) below which a clip holds
// nothing to hear: -50 dBFS, under any recorded voice and above dither and hum.
constexpr double kMinSeconds = 0.1;
constexpr double kSilentDb = -50.0;

constexpr int kFramesPerSecond = 100; // the decoder's
constexpr int kFrameSamples = kRecognizerSampleRate / kFramesPerSecond;

double decibels(double meanSquare)
{
    return 10.0 * std::log10(meanSquare + 1e-12);
}

// The level of each decoder frame (10 ms), dBFS.
std::vector<double> frameLevels(const std::vector<qint16> &pcm)
{
    std::vector<double> levels;
    for (std::size_t at = 0; at < pcm.size(); at += kFrameSamples) {
        const std::size_t end = std::min(pcm.size(), at + kFrameSamples);
        double sum = 0.0;
        for (std::size_t i = at; i < end; ++i)
            sum += double(pcm[i]) * pcm[i];
        levels.push_back(decibels(sum / double(end - at) / (32768.0 * 32768.0)));
    }
    return levels;
}

std::vector<qint16> ditheredPcm(const std::vector<float> &samples)
{
    // Triangular dither of one step from a fixed seed, so that a clip always gives the same
    // phones: digital silence (all zeros) would give the cepstra an energy of minus infinity.
    std::vector<qint16> pcm(samples.size());
    quint32 seed = 1;
    const auto uniform = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return double(seed) / 4294967296.0;
    };
    std::transform(samples.begin(), samples.end(), pcm.begin(), [&](float s) {
        const long v = std::lround(double(s) * 32767.0 + uniform() - uniform());
        return qint16(std::clamp(v, -32768L, 32767L));
    });
    return pcm;
}

// The clip as the decoder reads it (16 kHz, 16 bits), or why it cannot be read.
Expected<std::vector<qint16>, SpeechError> decoderPcm(const SpeechAudio &audio)
{
    if (audio.sampleRate < 4000 || audio.sampleRate > 384000)
        return failure(SpeechErrorKind::Damaged,
                       tr("The sound's sample rate (%1 Hz) is not one speech can be recognised at.")
                           .arg(audio.sampleRate));
    if (double(audio.samples.size()) < kMinSeconds * audio.sampleRate)
        return failure(
            SpeechErrorKind::Damaged,
            tr("The sound is too short to hold speech (less than a tenth of a second)."));
    if (!std::all_of(audio.samples.begin(), audio.samples.end(),
                     [](float s) { return std::isfinite(s); }))
        return failure(SpeechErrorKind::Damaged,
                       tr("The sound is damaged: some of its samples are not numbers."));
    std::vector<qint16> pcm = ditheredPcm(resampled(audio, kRecognizerSampleRate).samples);
    const std::vector<double> levels = frameLevels(pcm);
    if (*std::max_element(levels.begin(), levels.end()) < kSilentDb)
        return failure(SpeechErrorKind::Silent,
                       tr("The sound is silent: there is no speech to recognise. Check that the "
                          "clip is the one with the dialogue and that it is not muted."));
    return pcm;
}

// ---- Models and the decoder ------------------------------------------------------------------

struct ModelFiles {
    QByteArray acoustic, dictionary, phoneLm;
};

Expected<ModelFiles, SpeechError> modelFiles()
{
    const QString dir = speechModelDir();
    const ModelFiles files{QFile::encodeName(dir + QStringLiteral("/en-us")),
                           QFile::encodeName(dir + QStringLiteral("/cmudict-en-us.dict")),
                           QFile::encodeName(dir + QStringLiteral("/en-us-phone.lm.bin"))};
    const bool present = QFileInfo::exists(QFile::decodeName(files.acoustic) + "/mdef") &&
                         QFileInfo::exists(QFile::decodeName(files.dictionary)) &&
                         QFileInfo::exists(QFile::decodeName(files.phoneLm));
    if (!present)
        return failure(SpeechErrorKind::ModelMissing,
                       tr("The speech models are not installed (looked in %1; on Debian and Ubuntu "
                          "install the package pocketsphinx-en-us). Mouth shapes follow the "
                          "loudness only.")
                           .arg(dir));
    return files;
}

struct DecoderFree {
    void operator()(ps_decoder_t *ps) const { ps_free(ps); }
};
using Decoder = std::unique_ptr<ps_decoder_t, DecoderFree>;

// A decoder of its own for each call (loading the acoustic model takes ~40 ms), so that calls on
// several threads share nothing. Measured on synthetic speech (finbook-bench lipsync):
// - phone by phone, context-independent phones with a light phone language model (-lw 0.5)
//   match the most mouth shapes; context-dependent ones take 10 times as long (CPU time half
//   the clip's duration at a narrow beam) and match no more;
// - no beam pruning: the dialogue's grammar is a chain, cheap to search whole (CPU time 3 % of
//   a 98 s clip's duration), and with the usual beams its one path is sometimes pruned away;
// - silence removal off: it drops frames, and so shifts every time after it.
Decoder newDecoder(const ModelFiles &files)
{
    QByteArray options[][2] = {
        {"-hmm", files.acoustic},  {"-allphone_ci", "yes"}, {"-lw", "0.5"},
        {"-beam", "1e-80"},        {"-pbeam", "1e-80"},     {"-wbeam", "1e-80"},
        {"-remove_silence", "no"}, {"-fsgusefiller", "no"}, {"-bestpath", "no"}};
    std::vector<char *> argv;
    for (auto &[name, value] : options)
        argv.push_back(name.data()), argv.push_back(value.data());
    cmd_ln_t *config = cmd_ln_parse_r(nullptr, ps_args(), int(argv.size()), argv.data(), TRUE);
    if (!config)
        return nullptr;
    Decoder ps(ps_init(config));
    cmd_ln_free_r(config);
    return ps;
}

// ---- The dialogue's words and their pronunciations -------------------------------------------

using Pronunciation = std::vector<QByteArray>; // ARPAbet

struct DialogueWord {
    QString text;
    bool pauseAfter = false; // punctuation follows
};

const char *const kOnes[] = {"zero",    "one",     "two",       "three",    "four",
                             "five",    "six",     "seven",     "eight",    "nine",
                             "ten",     "eleven",  "twelve",    "thirteen", "fourteen",
                             "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"};
const char *const kTens[] = {"",      "",      "twenty",  "thirty", "forty",
                             "fifty", "sixty", "seventy", "eighty", "ninety"};

// "1984" as words ("one thousand nine hundred eighty four" moves the mouth as "nineteen
// eighty-four" nearly does); digit by digit from a million on.
QStringList numberWords(const QString &digits)
{
    bool ok = false;
    const long n = digits.size() <= 6 ? digits.toLong(&ok) : -1;
    QStringList words;
    if (!ok) {
        for (QChar d : digits)
            words << QLatin1String(kOnes[d.digitValue()]);
        return words;
    }
    const auto below1000 = [&words](long v) {
        if (v >= 100)
            words << QLatin1String(kOnes[v / 100]) << QStringLiteral("hundred");
        if (v % 100 >= 20)
            words << QLatin1String(kTens[v % 100 / 10]);
        if (v % 100 >= 20 && v % 10 > 0)
            words << QLatin1String(kOnes[v % 10]);
        else if (v % 100 > 0 && v % 100 < 20)
            words << QLatin1String(kOnes[v % 100]);
    };
    if (n >= 1000)
        below1000(n / 1000), words << QStringLiteral("thousand");
    below1000(n % 1000);
    return n == 0 ? QStringList{QStringLiteral("zero")} : words;
}

// The dialogue's words in lower case ASCII (accents dropped), numbers as words.
std::vector<DialogueWord> dialogueWords(const QString &dialogue)
{
    QString plain;
    for (QChar c : dialogue.normalized(QString::NormalizationForm_KD).toLower())
        if (!c.isMark())
            plain += c.unicode() < 128 ? c : QChar(u' ');
    static const QRegularExpression kWord(QStringLiteral("[a-z0-9]+(?:'[a-z0-9]+)*"));
    static const QRegularExpression kPunctuation(QStringLiteral("[,.;:!?()\"\\n]"));
    static const QRegularExpression kNotDigit(QStringLiteral("[^0-9]"));
    std::vector<DialogueWord> words;
    for (auto it = kWord.globalMatch(plain); it.hasNext();) {
        const QRegularExpressionMatch match = it.next();
        const qsizetype next = it.hasNext() ? it.peekNext().capturedStart() : plain.size();
        QString word = match.captured();
        const QStringList spoken =
            word.front().isDigit() ? numberWords(word.remove(kNotDigit)) : QStringList{word};
        for (const QString &w : spoken)
            words.push_back({w, false});
        words.back().pauseAfter =
            plain.mid(match.capturedEnd(), next - match.capturedEnd()).contains(kPunctuation);
    }
    return words;
}

const char *const kPhones[] = {"AA", "AE", "AH", "AO", "AW", "AY", "B",  "CH", "D",  "DH",
                               "EH", "ER", "EY", "F",  "G",  "HH", "IH", "IY", "JH", "K",
                               "L",  "M",  "N",  "NG", "OW", "OY", "P",  "R",  "S",  "SH",
                               "T",  "TH", "UH", "UW", "V",  "W",  "Y",  "Z",  "ZH", "SIL"};

bool isKnownPhone(QByteArrayView phone)
{
    return std::any_of(std::begin(kPhones), std::end(kPhones),
                       [&](const char *known) { return phone == known; });
}

Pronunciation phonesOf(QByteArrayView text)
{
    Pronunciation phones;
    for (const QByteArray &phone : text.toByteArray().simplified().split(' ')) {
        QByteArray bare = phone;
        bare.removeIf([](char c) { return c >= '0' && c <= '9'; }); // stress marks
        if (!bare.isEmpty())
            phones.push_back(bare);
    }
    return phones;
}

// Every pronunciation the dictionary gives the `words` ("read" and "read(2)").
QHash<QByteArray, std::vector<Pronunciation>> lookUp(const QByteArray &dictionary,
                                                     const std::vector<DialogueWord> &words)
{
    QHash<QByteArray, std::vector<Pronunciation>> found;
    QFile file(QFile::decodeName(dictionary));
    if (!file.open(QIODevice::ReadOnly))
        return found;
    QSet<QByteArray> wanted;
    for (const DialogueWord &word : words)
        wanted.insert(word.text.toLatin1());
    const QByteArray text = file.readAll();
    for (qsizetype at = 0; at < text.size();) {
        qsizetype end = text.indexOf('\n', at);
        end = end < 0 ? text.size() : end;
        const QByteArrayView line(text.constData() + at, end - at);
        at = end + 1;
        const qsizetype space = line.indexOf(' ');
        QByteArrayView head = line.first(std::max<qsizetype>(space, 0));
        if (const qsizetype paren = head.indexOf('('); paren > 0)
            head = head.first(paren);
        if (space > 0 && wanted.contains(head.toByteArray()))
            found[head.toByteArray()].push_back(phonesOf(line.sliced(space + 1)));
    }
    return found;
}

struct SpellingRule {
    const char *letters;
    const char *phones;
};

// English spelling to sound, roughly, for words the dictionary lacks (names, made-up words):
// tried in order at each letter, longer spellings first. A wrong vowel costs less than a word
// left out, which would pull every later phone off its time.
constexpr SpellingRule kSpellingRules[] = {
    {"tion", "SH AH N"}, {"sion", "ZH AH N"}, {"ough", "AO"}, {"augh", "AO"}, {"tch", "CH"},
    {"igh", "AY"},       {"th", "TH"},        {"sh", "SH"},   {"ch", "CH"},   {"ph", "F"},
    {"wh", "W"},         {"ck", "K"},         {"ng", "NG"},   {"qu", "K W"},  {"kn", "N"},
    {"wr", "R"},         {"gh", "G"},         {"ee", "IY"},   {"ea", "IY"},   {"oo", "UW"},
    {"ai", "EY"},        {"ay", "EY"},        {"oa", "OW"},   {"ow", "OW"},   {"ou", "AW"},
    {"oi", "OY"},        {"oy", "OY"},        {"au", "AO"},   {"aw", "AO"},   {"ie", "IY"},
    {"ey", "EY"},        {"ew", "UW"},        {"er", "ER"},   {"ir", "ER"},   {"ur", "ER"},
    {"ar", "AA R"},      {"or", "AO R"},      {"a", "AE"},    {"b", "B"},     {"c", "K"},
    {"d", "D"},          {"e", "EH"},         {"f", "F"},     {"g", "G"},     {"h", "HH"},
    {"i", "IH"},         {"j", "JH"},         {"k", "K"},     {"l", "L"},     {"m", "M"},
    {"n", "N"},          {"o", "AA"},         {"p", "P"},     {"q", "K"},     {"r", "R"},
    {"s", "S"},          {"t", "T"},          {"u", "AH"},    {"v", "V"},     {"w", "W"},
    {"x", "K S"},        {"z", "Z"}};

bool isVowel(char c)
{
    return c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u';
}

// The vowel a final silent "e" lengthens ("mate", "mete", "mite", "mote", "mute").
const char *longVowel(char c)
{
    switch (c) {
    case 'a':
        return "EY";
    case 'e':
        return "IY";
    case 'i':
        return "AY";
    case 'o':
        return "OW";
    default:
        return "UW";
    }
}

// The sound of the letters at `at` in `word`, and how many letters it takes.
std::pair<const char *, qsizetype> letterSound(const QByteArray &word, qsizetype at, bool silentE)
{
    const char c = word[at];
    const char next = at + 1 < word.size() ? word[at + 1] : '\0';
    if (c == next && !isVowel(c))
        return {"", 1}; // a doubled consonant is said once
    if ((c == 'c' || c == 'g') && (next == 'e' || next == 'i' || next == 'y'))
        return {c == 'c' ? "S" : "JH", 1};
    if (c == 'y')
        return {at == 0 ? "Y" : (next == '\0' ? "IY" : "IH"), 1};
    if (silentE && at == word.size() - 2 && isVowel(c))
        return {longVowel(c), 1};
    for (const SpellingRule &rule : kSpellingRules)
        if (word.sliced(at).startsWith(rule.letters))
            return {rule.phones, qsizetype(std::strlen(rule.letters))};
    return {"", 1}; // an apostrophe
}

Pronunciation spelt(QByteArray word)
{
    const bool silentE = word.size() > 3 && word.endsWith('e') && !isVowel(word[word.size() - 2]) &&
                         isVowel(word[word.size() - 3]);
    if (silentE)
        word.chop(1);
    QByteArray phones;
    for (qsizetype at = 0; at < word.size();) {
        const auto [sound, letters] = letterSound(word, at, silentE);
        phones += ' ' + QByteArray(sound);
        at += letters;
    }
    return phonesOf(phones);
}

struct SpokenWord {
    std::vector<Pronunciation> pronunciations;
    bool pauseAfter = false;
};

// The dialogue's words as the dictionary pronounces them, or as they are spelt (`unknown` lists
// those).
std::vector<SpokenWord> pronunciations(const QByteArray &dictionary,
                                       const std::vector<DialogueWord> &words, QStringList *unknown)
{
    const auto known = lookUp(dictionary, words);
    std::vector<SpokenWord> spoken;
    for (const DialogueWord &word : words) {
        std::vector<Pronunciation> prons = known.value(word.text.toLatin1());
        std::erase_if(prons, [](const Pronunciation &p) {
            return p.empty() || !std::all_of(p.begin(), p.end(), isKnownPhone);
        });
        if (prons.empty()) {
            if (!unknown->contains(word.text))
                unknown->append(word.text);
            prons = {spelt(word.text.toLatin1())};
        }
        if (!prons.front().empty())
            spoken.push_back({std::move(prons), word.pauseAfter});
        else if (!spoken.empty())
            spoken.back().pauseAfter |= word.pauseAfter;
    }
    return spoken;
}

// ---- The dialogue's grammar ------------------------------------------------------------------

struct FsgFree {
    void operator()(fsg_model_t *fsg) const { fsg_model_free(fsg); }
};
using Fsg = std::unique_ptr<fsg_model_t, FsgFree>;

// Each phone is a word of the grammar pronounced as itself, so that the search reports every
// phone with its frames. The prefix keeps them apart from dictionary words ("aa", "b").
QByteArray phoneWord(QByteArrayView phone)
{
    return "phone_" + phone.toByteArray().toLower();
}

enum class Pauses { AfterPunctuation, None };

// How likely a pause is where punctuation or the dialogue's end allows one. Elsewhere the search
// may not pause: given the chance, it took a third of a second of the bench's speech for a
// pause and squeezed the words around it. The pauses it cannot place are found from the sound's
// level afterwards (carvedPauses()).
constexpr double kPauseProbability = 0.1;

// The dialogue as a chain of phones: each word one of its pronunciations, a pause possible
// after the words punctuation follows and after the last. States: 0 the start, then per word
// the inner states of its pronunciations and its end state, then the end. Pauses are loops on
// the words' end states, as PocketSphinx's own fillers are, and the end is reached through a
// null transition: a grammar whose last word leads straight into the end state, or whose
// pauses are a "pause or nothing" pair of transitions, is never seen to reach its end.
Fsg alignmentGrammar(ps_decoder_t *ps, const std::vector<SpokenWord> &words, Pauses pauses)
{
    int states = 2;
    for (const SpokenWord &word : words)
        for (const Pronunciation &pron : word.pronunciations)
            states += int(pron.size()) - 1;
    states += int(words.size());
    logmath_t *lmath = ps_get_logmath(ps);
    const auto lw = float(cmd_ln_float32_r(ps_get_config(ps), "-lw"));
    Fsg fsg(fsg_model_init("dialogue", lmath, lw, states));
    if (!fsg)
        return nullptr;
    fsg->start_state = 0;
    fsg->final_state = states - 1;
    const auto logp = [&](double p) { return int32(logmath_log(lmath, p) * lw); };
    const int pause = fsg_model_word_add(fsg.get(), phoneWord("SIL").constData());
    int entry = 0, next = 1;
    for (std::size_t w = 0; w < words.size(); ++w) {
        const std::vector<Pronunciation> &prons = words[w].pronunciations;
        const int exit = next++;
        for (const Pronunciation &pron : prons)
            for (std::size_t i = 0, from = std::size_t(entry); i < pron.size(); ++i) {
                const int to = i + 1 == pron.size() ? exit : next++;
                const int word = fsg_model_word_add(fsg.get(), phoneWord(pron[i]).constData());
                const int32 p = i == 0 ? logp(1.0 / double(prons.size())) : 0;
                fsg_model_trans_add(fsg.get(), int32(from), to, p, word);
                from = std::size_t(to);
            }
        const bool pauseHere = words[w].pauseAfter || w + 1 == words.size();
        if (pauses == Pauses::AfterPunctuation && pauseHere)
            fsg_model_trans_add(fsg.get(), exit, exit, logp(kPauseProbability), pause);
        entry = exit;
    }
    fsg_model_null_trans_add(fsg.get(), entry, states - 1, 0);
    glist_free(fsg_model_null_trans_closure(fsg.get(), nullptr));
    return fsg;
}

// Teaches the decoder the phones as words (once a decoder).
bool addPhoneWords(ps_decoder_t *ps)
{
    return std::all_of(std::begin(kPhones), std::end(kPhones), [ps](const char *phone) {
        return ps_add_word(ps, phoneWord(phone).constData(), phone, FALSE) >= 0;
    });
}

Expected<bool, SpeechError> searchDialogue(ps_decoder_t *ps, const std::vector<SpokenWord> &words,
                                           Pauses pauses)
{
    const char *name = pauses == Pauses::None ? "dialogue without pauses" : "dialogue";
    const Fsg fsg = alignmentGrammar(ps, words, pauses);
    if (!fsg || ps_set_fsg(ps, name, fsg.get()) < 0 || ps_set_search(ps, name) < 0)
        return failure(
            SpeechErrorKind::Failed,
            tr("The dialogue could not be prepared for recognition: %1").arg(t_engineError));
    return true;
}

Expected<bool, SpeechError> searchPhones(ps_decoder_t *ps, const ModelFiles &files)
{
    if (ps_set_allphone_file(ps, "phones", files.phoneLm.constData()) < 0 ||
        ps_set_search(ps, "phones") < 0)
        return failure(SpeechErrorKind::Failed,
                       tr("The speech models are damaged: %1").arg(t_engineError));
    return true;
}

// ---- Decoding --------------------------------------------------------------------------------

constexpr int kBlockFrames = kFramesPerSecond / 4; // the search's steps between progress reports

// The clip's cepstra from the decoder's own front end, one row per frame.
struct Cepstra {
    std::vector<mfcc_t> values;
    std::vector<mfcc_t *> rows;
};

Cepstra cepstraOf(ps_decoder_t *ps, const std::vector<qint16> &pcm)
{
    fe_t *fe = ps_get_fe(ps);
    const auto width = std::size_t(fe_get_output_size(fe));
    const std::size_t capacity = pcm.size() / kFrameSamples + 2;
    Cepstra cep{std::vector<mfcc_t>(capacity * width), std::vector<mfcc_t *>(capacity)};
    for (std::size_t i = 0; i < capacity; ++i)
        cep.rows[i] = cep.values.data() + i * width;
    const int16 *samples = pcm.data();
    std::size_t left = pcm.size();
    int32 frames = int32(capacity) - 1, tail = 0;
    if (fe_start_utt(fe) < 0 ||
        fe_process_frames(fe, &samples, &left, cep.rows.data(), &frames, nullptr) < 0 ||
        fe_end_utt(fe, cep.rows[std::size_t(frames)], &tail) < 0)
        return {};
    cep.rows.resize(std::size_t(frames + tail));
    return cep;
}

// The mean of the cepstra of the frames with energy (c0 > 0), as PocketSphinx's batch mean
// normalisation takes it. Given to the decoder as the start of its running mean, it normalises
// the clip as a batch would while the search still goes block by block; the running mean
// otherwise starts from the model's average speaker, and the clip's first second comes out
// wrong (on the bench's short sentences, 10 to 14 points fewer mouth shapes right).
void startMeanAtClipMean(ps_decoder_t *ps, const Cepstra &cep)
{
    feat_t *feat = ps_get_feat(ps);
    const auto width = std::size_t(feat_cepsize(feat));
    std::vector<mfcc_t> mean(width, 0);
    int counted = 0;
    for (const mfcc_t *row : cep.rows) {
        if (row[0] <= 0)
            continue;
        for (std::size_t i = 0; i < width; ++i)
            mean[i] += row[i];
        ++counted;
    }
    if (counted == 0)
        return;
    for (mfcc_t &m : mean)
        m /= mfcc_t(counted);
    cmn_live_set(feat->cmn_struct, mean.data());
}

// Runs the decoder's search over the clip. False when the search found no path (the dialogue's
// grammar does not fit the sound).
Expected<bool, SpeechError> decode(ps_decoder_t *ps, Cepstra &cep, const SpeechProgress &progress)
{
    const auto failed = [] {
        return failure(SpeechErrorKind::Failed,
                       tr("Speech recognition failed: %1").arg(t_engineError));
    };
    if (ps_start_utt(ps) < 0)
        return failed();
    startMeanAtClipMean(ps, cep);
    const auto total = int(cep.rows.size());
    for (int at = 0; at < total; at += kBlockFrames) {
        if (progress && !progress(double(at) / total)) {
            ps_end_utt(ps);
            return failure(SpeechErrorKind::Canceled, tr("Lip sync was canceled."));
        }
        const int frames = std::min(kBlockFrames, total - at);
        if (ps_process_cep(ps, cep.rows.data() + at, frames, FALSE, FALSE) < 0)
            return failed();
    }
    if (ps_end_utt(ps) < 0)
        return failed();
    return ps_get_hyp(ps, nullptr) != nullptr;
}

// Half the window past the frame's start: a 25.6 ms window every 10 ms sees a change between
// two frames best 7.8 ms after the later frame starts.
constexpr double kFrameCentre = (0.025625 - 0.01) / 2;

// "phone_aa" (the dialogue's grammar) or "AA" (phone by phone) as "AA"; silence and noise
// ("phone_sil", "SIL", "+NSN+") as "SIL".
QString phoneName(const char *word)
{
    QByteArray name(word);
    if (name.startsWith("phone_"))
        name = name.sliced(6).toUpper();
    return isKnownPhone(name) ? QString::fromLatin1(name) : QStringLiteral("SIL");
}

void appendPhone(std::vector<TimedPhone> &phones, const QString &phone, double start, double end)
{
    if (end <= start)
        return;
    if (!phones.empty() && phones.back().phone == phone && phone == QLatin1String("SIL"))
        phones.back().end = end;
    else
        phones.push_back({phone, start, end});
}

// The search's phones without gaps from 0 to `duration`.
std::vector<TimedPhone> timedPhones(ps_decoder_t *ps, double duration)
{
    const double offset = kFrameCentre;
    std::vector<TimedPhone> phones;
    double reached = 0.0;
    for (ps_seg_t *seg = ps_seg_iter(ps); seg; seg = ps_seg_next(seg)) {
        int first = 0, last = 0;
        ps_seg_frames(seg, &first, &last);
        const double start = std::clamp(first * 0.01 + offset, reached, duration);
        const double end = std::clamp((last + 1) * 0.01 + offset, start, duration);
        appendPhone(phones, QStringLiteral("SIL"), reached, start);
        appendPhone(phones, phoneName(ps_seg_word(seg)), start, end);
        reached = std::max(reached, end);
    }
    appendPhone(phones, QStringLiteral("SIL"), reached, duration);
    if (phones.size() > 1 && phones.front().phone == QLatin1String("SIL") &&
        phones.front().end < 2 * offset) // the offset's sliver
        phones[1].start = 0.0, phones.erase(phones.begin());
    return phones;
}

// A pause is a stretch this long at most this far above the clip's quiet floor (and well below
// its speech), longer than a stop's closure.
constexpr double kMinPauseSeconds = 0.15;
constexpr double kPauseAboveFloorDb = 10.0, kPauseBelowSpeechDb = 25.0;

// `phones` with the pauses a phone spans (a silence the grammar could not put between those
// words) given to SIL.
std::vector<TimedPhone> carvedPauses(const std::vector<TimedPhone> &phones,
                                     const std::vector<double> &levels)
{
    std::vector<double> sorted = levels;
    std::sort(sorted.begin(), sorted.end());
    const double quiet = std::min(sorted[sorted.size() / 10] + kPauseAboveFloorDb,
                                  sorted[sorted.size() * 95 / 100] - kPauseBelowSpeechDb);
    const auto minFrames = int(kMinPauseSeconds * kFramesPerSecond);
    std::vector<TimedPhone> carved;
    for (const TimedPhone &p : phones) {
        const auto first = int(std::lround((p.start - kFrameCentre) * kFramesPerSecond));
        const auto last = int(std::lround((p.end - kFrameCentre) * kFramesPerSecond));
        double from = p.start;
        for (int f = std::max(first, 0); f < std::min(last, int(levels.size()));) {
            int run = f;
            while (run < last && run < int(levels.size()) && levels[std::size_t(run)] < quiet)
                ++run;
            if (run - f >= minFrames && p.phone != QLatin1String("SIL")) {
                const double pauseStart = std::max(from, f * 0.01 + kFrameCentre);
                const double pauseEnd = std::min(p.end, run * 0.01 + kFrameCentre);
                appendPhone(carved, p.phone, from, pauseStart);
                appendPhone(carved, QStringLiteral("SIL"), pauseStart, pauseEnd);
                from = pauseEnd;
            }
            f = std::max(run, f + 1);
        }
        appendPhone(carved, p.phone, from, p.end);
    }
    return carved;
}

// The searches of one call over one clip. The first reports progress; a retry reports the
// progress done (it takes a few percent of the first one's time) and may still cancel.
struct Recognition {
    ps_decoder_t *ps;
    Cepstra &cep;
    double duration; // seconds
    const SpeechProgress &progress;
    int searches = 0;

    Expected<bool, SpeechError> run()
    {
        const SpeechProgress retry = [this](double) { return !progress || progress(1.0); };
        return decode(ps, cep, searches++ ? retry : progress);
    }

    // The dialogue's phones, or none when there is no dialogue or it does not fit the sound.
    Expected<std::optional<std::vector<TimedPhone>>, SpeechError>
    aligned(const std::vector<SpokenWord> &words)
    {
        for (const Pauses pauses : {Pauses::AfterPunctuation, Pauses::None}) {
            if (words.empty())
                break;
            const auto ready = searchDialogue(ps, words, pauses);
            const auto found = ready ? run() : ready;
            if (!found)
                return unexpected(found.error());
            if (*found)
                return std::optional(timedPhones(ps, duration));
        }
        return std::optional<std::vector<TimedPhone>>();
    }

    // The phones heard phone by phone, then aligned again as if they were the dialogue: the
    // recogniser hears context-independent phones, the aligner places context-dependent ones,
    // and their boundaries land nearer the truth (2.5 points more mouth shapes right on the bench).
    Expected<std::vector<TimedPhone>, SpeechError> heard(const ModelFiles &files)
    {
        const auto ready = searchPhones(ps, files);
        const auto found = ready ? run() : ready;
        if (!found)
            return unexpected(found.error());
        std::vector<TimedPhone> phones = timedPhones(ps, duration);
        std::vector<SpokenWord> words;
        for (const TimedPhone &p : phones) {
            if (p.phone != QLatin1String("SIL"))
                words.push_back({{Pronunciation{p.phone.toLatin1()}}, false});
            else if (!words.empty())
                words.back().pauseAfter = true;
        }
        auto again = aligned(words); // where this fails, the phones heard stay
        if (!again)
            return unexpected(again.error());
        return again->value_or(std::move(phones));
    }
};

// ---- Loudness -------------------------------------------------------------------------------

constexpr double kMinRangeDb = 20.0; // a clip without pauses still has a range to measure in
// Shares of the clip's loudness range where the mouth half opens (B) and opens (D), and how far
// past them it must go to change back: without that, a level near a threshold flickers.
constexpr double kHalfOpen = 0.3, kOpen = 0.65, kHysteresis = 0.06;

// The level of each animation frame, dBFS.
std::vector<double> videoFrameLevels(const SpeechAudio &audio, double fps)
{
    const double seconds = double(audio.samples.size()) / audio.sampleRate;
    const auto frames = std::size_t(std::max(1.0, std::ceil(seconds * fps - 1e-9)));
    std::vector<double> levels(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        const auto from = std::size_t(double(i) / fps * audio.sampleRate);
        const auto to =
            std::min(audio.samples.size(), std::size_t(double(i + 1) / fps * audio.sampleRate));
        double sum = 0.0;
        for (std::size_t k = from; k < to; ++k)
            sum += double(audio.samples[k]) * audio.samples[k];
        levels[i] = decibels(sum / double(std::max<std::size_t>(1, to - from)));
    }
    return levels;
}

MouthShape loudnessShape(MouthShape now, double share)
{
    // The threshold a shape is held at lies lower than the one it is reached at.
    const auto reaches = [&](double threshold, bool held) {
        return share >= threshold + (held ? -kHysteresis : kHysteresis) / 2;
    };
    if (reaches(kOpen, now == MouthShape::D))
        return MouthShape::D;
    if (reaches(kHalfOpen, now != MouthShape::X))
        return MouthShape::B;
    return MouthShape::X;
}

} // namespace

SpeechAudio resampled(const SpeechAudio &audio, int rate)
{
    if (audio.samples.empty() || audio.sampleRate <= 0 || rate <= 0)
        return {{}, std::max(rate, 1)};
    if (audio.sampleRate == rate)
        return audio;
    // Input samples per output sample; the cut-off in cycles per input sample.
    const double step = double(audio.sampleRate) / rate;
    const double cutoff = 0.5 * kPassBand * std::min(1.0, 1.0 / step);
    const double half = kSincZeros / (2.0 * cutoff); // the kernel's half width, input samples
    // The kernel tabulated at kPhases points per input sample, read with linear interpolation.
    constexpr int kPhases = 256;
    std::vector<float> kernel(std::size_t(std::ceil(half * kPhases)) + 2);
    for (std::size_t i = 0; i < kernel.size(); ++i) {
        const double d = double(i) / kPhases, x = std::numbers::pi * 2.0 * cutoff * d;
        const double sinc = x == 0.0 ? 1.0 : std::sin(x) / x;
        kernel[i] = d >= half ? 0.0f : float(2.0 * cutoff * sinc * blackman(d / half));
    }
    const auto tap = [&kernel](double d) {
        const double at = std::abs(d) * kPhases;
        const auto i = std::size_t(at);
        return i + 1 >= kernel.size() ? 0.0
                                      : kernel[i] + (at - double(i)) * (kernel[i + 1] - kernel[i]);
    };
    const auto n = qint64(audio.samples.size());
    SpeechAudio out{std::vector<float>(std::size_t(double(n) / step)), rate};
    for (std::size_t j = 0; j < out.samples.size(); ++j) {
        const double t = double(j) * step;
        const qint64 from = std::max<qint64>(0, qint64(std::ceil(t - half)));
        const qint64 to = std::min<qint64>(n - 1, qint64(std::floor(t + half)));
        double sum = 0.0;
        for (qint64 k = from; k <= to; ++k)
            sum += audio.samples[std::size_t(k)] * tap(t - double(k));
        out.samples[j] = float(sum);
    }
    return out;
}

QString speechModelDir()
{
    const QString overridden = qEnvironmentVariable("FINBOOK_SPEECH_MODEL_DIR");
    if (!overridden.isEmpty())
        return overridden;
    return QFile::decodeName(FINBOOK_POCKETSPHINX_MODELDIR) + QStringLiteral("/en-us");
}

Expected<RecognizedSpeech, SpeechError>
recognizePhones(const SpeechAudio &audio, const QString &dialogue, const SpeechProgress &progress)
{
    const auto pcm = decoderPcm(audio);
    if (!pcm)
        return unexpected(pcm.error());
    const auto files = modelFiles();
    if (!files)
        return unexpected(files.error());
    routeEngineLog();
    t_engineError.clear();
    const Decoder ps = newDecoder(*files);
    Cepstra cep = ps && addPhoneWords(ps.get()) ? cepstraOf(ps.get(), *pcm) : Cepstra{};
    if (cep.rows.empty())
        return failure(SpeechErrorKind::ModelMissing,
                       tr("The speech models could not be loaded (%1). Mouth shapes follow the "
                          "loudness only.")
                           .arg(t_engineError));
    RecognizedSpeech result;
    const std::vector<SpokenWord> words =
        pronunciations(files->dictionary, dialogueWords(dialogue), &result.unknownWords);
    Recognition recognition{ps.get(), cep, double(pcm->size()) / kRecognizerSampleRate, progress};
    auto aligned = recognition.aligned(words);
    if (!aligned)
        return unexpected(aligned.error());
    result.followedDialogue = aligned->has_value();
    if (!words.empty() && !result.followedDialogue)
        result.note = tr("The dialogue does not match the sound: the mouth follows the phones "
                         "heard, without the dialogue.");
    auto phones = result.followedDialogue ? std::move(**aligned) : recognition.heard(*files);
    if (!phones)
        return unexpected(phones.error());
    result.phones = carvedPauses(*phones, frameLevels(*pcm));
    if (progress)
        progress(1.0);
    return result;
}

std::vector<MouthCue> loudnessCues(const SpeechAudio &audio, double fps)
{
    if (audio.samples.empty() || audio.sampleRate <= 0 || !(fps > 0.0))
        return {};
    const std::vector<double> levels = videoFrameLevels(audio, fps);
    // The clip's own range: its quiet floor (the 10th percentile, or silence where that is
    // quieter) to its loud peaks (the 95th).
    std::vector<double> sorted = levels;
    std::sort(sorted.begin(), sorted.end());
    const double floor = std::max(sorted[sorted.size() / 10], kSilentDb);
    const double peak = std::max(sorted[sorted.size() * 95 / 100], floor + kMinRangeDb);
    std::vector<MouthCue> cues;
    MouthShape shape = MouthShape::X;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const double share = levels[i] < kSilentDb ? 0.0 : (levels[i] - floor) / (peak - floor);
        shape = loudnessShape(shape, share);
        if (cues.empty() || cues.back().shape != shape)
            cues.push_back({double(i) / fps, shape});
    }
    return cues;
}

} // namespace finbook::model::lipsync
