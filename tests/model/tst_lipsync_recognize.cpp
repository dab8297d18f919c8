// Recognising the phones of speech for lip sync (issue 49): espeak-ng speaks a sentence and
// times its phonemes; with the sentence as the dialogue, every closure of the lips it says
// (M, B, P) is found within two frames at 24 fps. A silent, damaged or cancelled clip and
// missing models give an error of their kind; the loudness fallback closes the mouth on
// silence and opens it on a loud stretch; the resampler keeps speech and drops what the lower
// rate cannot hold.
#include <finbook/model/lipsync/speech_recognizer.h>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <espeak-ng/speak_lib.h>
#include <numbers>
#include <thread>

using namespace finbook::model::lipsync;

class TestLipsyncRecognize : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void closuresLandOnClosedMouths();
    void withoutDialogueThePhonesCoverTheClip();
    void unknownWordsAreSpeltAndListed();
    void callsOnTwoThreadsAgree();
    void progressRisesToTheEnd();
    void cancelStopsAtOnce();
    void silentClipIsRefused();
    void damagedClipsAreRefused();
    void missingModelsAreSaid();
    void loudnessCuesCloseOnSilenceAndOpenOnLoudness();
    void resamplingKeepsSpeechAndDropsWhatDoesNotFit();

private:
    bool m_haveModels = false;
    bool m_haveEspeak = false;
};

namespace {
constexpr double kFps = 24.0;
const QString kSentence = QStringLiteral("Bob made my mom a pie.");

struct Spoken {
    SpeechAudio audio;
    std::vector<TimedPhone> closures; // espeak's m, b, p
};

// espeak-ng calls back on the synthesising thread; one synthesis at a time.
std::vector<short> *g_samples = nullptr;
std::vector<std::pair<QByteArray, double>> *g_phonemes = nullptr;

int collect(short *wav, int count, espeak_EVENT *event)
{
    if (wav && count > 0)
        g_samples->insert(g_samples->end(), wav, wav + count);
    for (; event && event->type != espeakEVENT_LIST_TERMINATED; ++event)
        if (event->type == espeakEVENT_PHONEME)
            g_phonemes->push_back({QByteArray(event->id.string, int(strnlen(event->id.string, 8))),
                                   event->audio_position / 1000.0});
    return 0;
}

Spoken speak(const QString &text)
{
    std::vector<short> samples;
    std::vector<std::pair<QByteArray, double>> phonemes;
    g_samples = &samples, g_phonemes = &phonemes;
    const QByteArray utf8 = text.toUtf8();
    espeak_SetVoiceByName("en-us");
    espeak_SetParameter(espeakRATE, 160, 0);
    espeak_Synth(utf8.constData(), std::size_t(utf8.size()) + 1, 0, POS_CHARACTER, 0,
                 espeakCHARS_UTF8, nullptr, nullptr);
    espeak_Synchronize();
    g_samples = nullptr, g_phonemes = nullptr;
    Spoken spoken;
    spoken.audio.sampleRate = 22050; // espeak-ng's
    for (short s : samples)
        spoken.audio.samples.push_back(float(s) / 32768.0f);
    for (std::size_t i = 0; i + 1 < phonemes.size(); ++i)
        if (phonemes[i].first == "m" || phonemes[i].first == "b" || phonemes[i].first == "p")
            spoken.closures.push_back({QString::fromLatin1(phonemes[i].first).toUpper(),
                                       phonemes[i].second, phonemes[i + 1].second});
    return spoken;
}

bool isClosure(const QString &phone)
{
    return phone == u"M" || phone == u"B" || phone == u"P";
}

double middle(const TimedPhone &p)
{
    return (p.start + p.end) / 2;
}

// Phones from 0 to the clip's end, each after the last, none empty.
void verifyCoverage(const std::vector<TimedPhone> &phones, double duration)
{
    QVERIFY(!phones.empty());
    QCOMPARE(phones.front().start, 0.0);
    QVERIFY(std::abs(phones.back().end - duration) < 0.01);
    for (std::size_t i = 0; i < phones.size(); ++i) {
        QVERIFY2(phones[i].end > phones[i].start, qPrintable(phones[i].phone));
        if (i > 0)
            QCOMPARE(phones[i].start, phones[i - 1].end);
    }
}

SpeechAudio tone(double seconds, int rate, double hz, double amplitude)
{
    SpeechAudio audio{std::vector<float>(std::size_t(seconds * rate)), rate};
    for (std::size_t i = 0; i < audio.samples.size(); ++i)
        audio.samples[i] =
            float(amplitude * std::sin(2 * std::numbers::pi * hz * double(i) / rate));
    return audio;
}

// The amplitude of the `hz` component of `audio`, away from its ends.
double amplitudeAt(const SpeechAudio &audio, double hz)
{
    double c = 0, s = 0;
    const std::size_t from = audio.samples.size() / 4, to = audio.samples.size() * 3 / 4;
    for (std::size_t i = from; i < to; ++i) {
        const double phase = 2 * std::numbers::pi * hz * double(i) / audio.sampleRate;
        c += audio.samples[i] * std::cos(phase), s += audio.samples[i] * std::sin(phase);
    }
    return 2 * std::hypot(c, s) / double(to - from);
}
} // namespace

void TestLipsyncRecognize::initTestCase()
{
    const QString dir = speechModelDir();
    m_haveModels = QFileInfo::exists(dir + QStringLiteral("/en-us/mdef")) &&
                   QFileInfo::exists(dir + QStringLiteral("/cmudict-en-us.dict")) &&
                   QFileInfo::exists(dir + QStringLiteral("/en-us-phone.lm.bin"));
    m_haveEspeak =
        espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                          espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT) > 0;
    if (m_haveEspeak)
        espeak_SetSynthCallback(collect);
}

#define REQUIRE_SPEECH()                                                                           \
    do {                                                                                           \
        if (!m_haveModels)                                                                         \
            QSKIP("PocketSphinx's US English models are missing (bash .ci/setup installs "         \
                  "pocketsphinx-en-us)");                                                          \
        if (!m_haveEspeak)                                                                         \
            QSKIP("espeak-ng could not start");                                                    \
    } while (false)

void TestLipsyncRecognize::closuresLandOnClosedMouths()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(kSentence);
    QCOMPARE(int(spoken.closures.size()), 7); // B-b m m m-m p
    const auto result = recognizePhones(spoken.audio, kSentence, {});
    QVERIFY2(result, qPrintable(result ? QString() : result.error().message));
    QVERIFY(result->followedDialogue);
    QVERIFY(result->unknownWords.isEmpty());
    std::vector<TimedPhone> closures;
    std::copy_if(result->phones.begin(), result->phones.end(), std::back_inserter(closures),
                 [](const TimedPhone &p) { return isClosure(p.phone); });
    QCOMPARE(closures.size(), spoken.closures.size());
    for (std::size_t i = 0; i < closures.size(); ++i) {
        const double framesOff = std::abs(middle(closures[i]) - middle(spoken.closures[i])) * kFps;
        QVERIFY2(framesOff <= 2.0, qPrintable(QStringLiteral("%1 at %2 s is %3 frames off")
                                                  .arg(spoken.closures[i].phone)
                                                  .arg(spoken.closures[i].start)
                                                  .arg(framesOff)));
    }
}

void TestLipsyncRecognize::withoutDialogueThePhonesCoverTheClip()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(kSentence);
    const auto result = recognizePhones(spoken.audio, QString(), {});
    QVERIFY2(result, qPrintable(result ? QString() : result.error().message));
    QVERIFY(!result->followedDialogue);
    QVERIFY(result->note.isEmpty());
    verifyCoverage(result->phones, double(spoken.audio.samples.size()) / 22050);
    // Speech is heard: most of the clip is phones, not silence.
    double speech = 0;
    for (const TimedPhone &p : result->phones)
        speech += p.phone == u"SIL" ? 0.0 : p.end - p.start;
    QVERIFY(speech > 0.5 * result->phones.back().end);
}

void TestLipsyncRecognize::unknownWordsAreSpeltAndListed()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(QStringLiteral("Bob made my mom a zorblax."));
    const auto result =
        recognizePhones(spoken.audio, QStringLiteral("Bob made my mom a Zorblax!"), {});
    QVERIFY2(result, qPrintable(result ? QString() : result.error().message));
    QCOMPARE(result->unknownWords, QStringList{QStringLiteral("zorblax")});
    QVERIFY(result->followedDialogue);
    verifyCoverage(result->phones, double(spoken.audio.samples.size()) / 22050);
}

// One decoder per call: the same clip on two threads at once gives what it gives on one.
void TestLipsyncRecognize::callsOnTwoThreadsAgree()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(kSentence);
    const auto alone = recognizePhones(spoken.audio, kSentence, {});
    QVERIFY(alone);
    std::vector<TimedPhone> results[2];
    std::thread a([&] { results[0] = recognizePhones(spoken.audio, kSentence, {})->phones; });
    std::thread b([&] { results[1] = recognizePhones(spoken.audio, QString(), {})->phones; });
    a.join(), b.join();
    const auto without = recognizePhones(spoken.audio, QString(), {});
    QVERIFY(without);
    const auto same = [](const std::vector<TimedPhone> &x, const std::vector<TimedPhone> &y) {
        return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](const auto &p, const auto &q) {
            return p.phone == q.phone && p.start == q.start && p.end == q.end;
        });
    };
    QVERIFY(same(results[0], alone->phones));
    QVERIFY(same(results[1], without->phones));
}

void TestLipsyncRecognize::progressRisesToTheEnd()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(kSentence);
    std::vector<double> seen;
    const auto result = recognizePhones(spoken.audio, kSentence, [&seen](double p) {
        seen.push_back(p);
        return true;
    });
    QVERIFY(result);
    QVERIFY(seen.size() > 2);
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    QCOMPARE(seen.front(), 0.0);
    QCOMPARE(seen.back(), 1.0);
}

void TestLipsyncRecognize::cancelStopsAtOnce()
{
    REQUIRE_SPEECH();
    const Spoken spoken = speak(kSentence);
    for (const QString &dialogue : {kSentence, QString()}) {
        int calls = 0;
        const auto result = recognizePhones(spoken.audio, dialogue, [&calls](double p) {
            ++calls;
            return p < 0.3;
        });
        QVERIFY(!result);
        QCOMPARE(result.error().kind, SpeechErrorKind::Canceled);
        QVERIFY(!result.error().message.isEmpty());
        int callsAfterCancel = 0;
        recognizePhones(spoken.audio, dialogue, [&callsAfterCancel](double) {
            ++callsAfterCancel;
            return false;
        });
        QCOMPARE(callsAfterCancel, 1); // nothing more is asked once it said no
        QVERIFY(calls >= 2);
    }
}

void TestLipsyncRecognize::silentClipIsRefused()
{
    for (const float level : {0.0f, 1e-4f}) { // digital silence, and hiss at -80 dBFS
        SpeechAudio silence{std::vector<float>(48000), 48000};
        for (std::size_t i = 0; i < silence.samples.size(); ++i)
            silence.samples[i] = i % 2 ? level : -level;
        const auto result = recognizePhones(silence, kSentence, {});
        QVERIFY(!result);
        QCOMPARE(result.error().kind, SpeechErrorKind::Silent);
        QVERIFY(result.error().message.contains(QStringLiteral("silent")));
    }
}

void TestLipsyncRecognize::damagedClipsAreRefused()
{
    SpeechAudio notANumber = tone(1.0, 16000, 440, 0.5);
    notANumber.samples[100] = std::nanf("");
    const SpeechAudio badRate{std::vector<float>(1000, 0.1f), 0};
    const SpeechAudio tooShort = tone(0.05, 16000, 440, 0.5);
    for (const SpeechAudio &audio : {notANumber, badRate, tooShort, SpeechAudio{}}) {
        const auto result = recognizePhones(audio, QString(), {});
        QVERIFY(!result);
        QCOMPARE(result.error().kind, SpeechErrorKind::Damaged);
        QVERIFY(!result.error().message.isEmpty());
    }
}

void TestLipsyncRecognize::missingModelsAreSaid()
{
    QTemporaryDir empty;
    QVERIFY(empty.isValid());
    qputenv("FINBOOK_SPEECH_MODEL_DIR", QFile::encodeName(empty.path()));
    const auto result = recognizePhones(tone(1.0, 16000, 440, 0.5), QString(), {});
    qunsetenv("FINBOOK_SPEECH_MODEL_DIR");
    QVERIFY(!result);
    QCOMPARE(result.error().kind, SpeechErrorKind::ModelMissing);
    QVERIFY(result.error().message.contains(empty.path()));
}

void TestLipsyncRecognize::loudnessCuesCloseOnSilenceAndOpenOnLoudness()
{
    // Half a second each: silence, a loud tone, a soft one, silence.
    SpeechAudio audio{{}, 48000};
    for (const double amplitude : {0.0, 0.5, 0.05, 0.0}) {
        const SpeechAudio part = tone(0.5, 48000, 220, amplitude);
        audio.samples.insert(audio.samples.end(), part.samples.begin(), part.samples.end());
    }
    const std::vector<MouthCue> cues = loudnessCues(audio, kFps);
    const auto shapeAt = [&cues](double t) {
        MouthShape shape = MouthShape::X;
        for (const MouthCue &cue : cues)
            if (cue.start <= t)
                shape = cue.shape;
        return shape;
    };
    QVERIFY(!cues.empty());
    QCOMPARE(cues.front().start, 0.0);
    QCOMPARE(shapeAt(0.25), MouthShape::X);
    QCOMPARE(shapeAt(0.75), MouthShape::D);
    QCOMPARE(shapeAt(1.25), MouthShape::B);
    QCOMPARE(shapeAt(1.75), MouthShape::X);
    QVERIFY(cues.size() <= 5); // no flicker inside a stretch
    QVERIFY(loudnessCues(SpeechAudio{}, kFps).empty());
    QVERIFY(loudnessCues(audio, 0.0).empty());
}

void TestLipsyncRecognize::resamplingKeepsSpeechAndDropsWhatDoesNotFit()
{
    const SpeechAudio voice = resampled(tone(1.0, 44100, 1000, 0.5), kRecognizerSampleRate);
    QCOMPARE(voice.sampleRate, kRecognizerSampleRate);
    QCOMPARE(int(voice.samples.size()), kRecognizerSampleRate);
    QVERIFY(std::abs(amplitudeAt(voice, 1000) - 0.5) < 0.005);
    // 12 kHz does not fit under 16 kHz's 8 kHz: nothing of it, nor its 4 kHz alias, is left.
    const SpeechAudio high = resampled(tone(1.0, 44100, 12000, 0.5), kRecognizerSampleRate);
    QVERIFY(amplitudeAt(high, 4000) < 0.5e-3);
    const SpeechAudio up = resampled(tone(1.0, 8000, 1000, 0.5), kRecognizerSampleRate);
    QVERIFY(std::abs(amplitudeAt(up, 1000) - 0.5) < 0.005);
    QVERIFY(resampled(SpeechAudio{}, kRecognizerSampleRate).samples.empty());
}

QTEST_GUILESS_MAIN(TestLipsyncRecognize)
#include "tst_lipsync_recognize.moc"
