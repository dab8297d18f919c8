// Decoding sound (FFmpeg's libraries): the formats an animator brings (WAV, FLAC, MP3,
// Ogg/Opus, AAC/M4A, made here by ffmpeg's `sine` source), hostile or cut-short files refused
// with a sentence, the waveform, the mix, and the cache that decodes on a worker thread.
#include "sound_support.h"

#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/sound_decode.h>
#include <finbook/model/sound/sound_mix.h>

#include <QtTest>

#include <random>
#include <sys/resource.h>

using namespace finbook::model;
using namespace sound_test;

class TestSoundDecode : public QObject {
    Q_OBJECT
private slots:
    void decodesWav();
    void decodesFormats_data();
    void decodesFormats();
    void refusesWhatIsNotSound();
    void refusesCutShortSound();
    void waveformFollowsTheSound();
    void mixesClipsAtTheirStartAndVolume();
    void cacheDecodesOffTheGuiThread();
    void refusesRatesOutsideTheRange();
    void refusesMoreSoundThanItsBytesHold();
    void soundtrackSharesOneBudget();
};

namespace {
// How far this process's peak resident memory rose while `work` ran (the peak so far can hide
// a rise below it, never invent one).
template <typename Work> long peakRiseMiB(Work &&work)
{
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    work();
    getrusage(RUSAGE_SELF, &after);
    return (after.ru_maxrss - before.ru_maxrss) / 1024;
}
} // namespace

void TestSoundDecode::decodesWav()
{
    auto sound = decodeSound(sineWav(1.0, 44100));
    QVERIFY2(sound, sound ? "" : qPrintable(sound.error()));
    QVERIFY(std::abs(sound->seconds() - 1.0) < 0.01);
    // Resampled to stereo at kSoundRate: both channels carry the mono sine, at about half scale.
    float peak = 0.0f;
    for (qint16 s : sound->samples)
        peak = std::max(peak, std::abs(float(s) * DecodedSound::kScale));
    QVERIFY(peak > 0.3f && peak < 0.6f);
    QCOMPARE(sound->samples[1000 * 2], sound->samples[1000 * 2 + 1]);
}

void TestSoundDecode::decodesFormats_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("codec");
    QTest::newRow("flac") << QStringLiteral("s.flac") << QStringList();
    QTest::newRow("mp3") << QStringLiteral("s.mp3") << QStringList();
    QTest::newRow("ogg vorbis") << QStringLiteral("s.ogg") << QStringList();
    QTest::newRow("opus") << QStringLiteral("s.opus") << QStringList();
    QTest::newRow("m4a aac") << QStringLiteral("s.m4a")
                             << QStringList{QStringLiteral("-c:a"), QStringLiteral("aac")};
}

void TestSoundDecode::decodesFormats()
{
    QFETCH(QString, file);
    QFETCH(QStringList, codec);
    QTemporaryDir dir;
    const QByteArray bytes = ffmpegSine(dir, file, 1.5, codec);
    if (bytes.isEmpty())
        QSKIP("ffmpeg cannot make this format here");
    auto sound = decodeSound(bytes);
    QVERIFY2(sound, sound ? "" : qPrintable(sound.error()));
    // Encoders pad a little (priming samples, whole frames).
    QVERIFY2(std::abs(sound->seconds() - 1.5) < 0.1, qPrintable(QString::number(sound->seconds())));
}

void TestSoundDecode::refusesWhatIsNotSound()
{
    std::mt19937 random(24);
    QByteArray noise(100000, '\0');
    for (char &c : noise)
        c = char(random());
    QByteArray png("\x89PNG\r\n\x1a\n", 8);
    png += noise.left(200);
    QByteArray header = sineWav(0.5).left(44); // a WAV with no samples at all
    for (const QByteArray &bytes :
         {QByteArray(), noise, png, QByteArray("hello, this is text\n"), header}) {
        auto sound = decodeSound(bytes);
        QVERIFY(!sound);
        QVERIFY(!sound.error().isEmpty());
        QVERIFY(sound.error().endsWith(QLatin1Char('.')));
    }
}

void TestSoundDecode::refusesCutShortSound()
{
    const QByteArray wav = sineWav(4.0);
    auto sound = decodeSound(wav.left(wav.size() / 3)); // the header still says 4 s
    QVERIFY(!sound);
    QVERIFY2(sound.error().contains(QStringLiteral("incomplete")), qPrintable(sound.error()));
    QTemporaryDir dir;
    for (const QString &file : {QStringLiteral("cut.flac"), QStringLiteral("cut.mp3")}) {
        const QByteArray whole = ffmpegSine(dir, file, 4.0);
        if (whole.isEmpty())
            QSKIP("no ffmpeg");
        auto cut = decodeSound(whole.left(whole.size() / 3));
        QVERIFY2(!cut, qPrintable(file));
        QVERIFY2(cut.error().contains(QStringLiteral("incomplete")), qPrintable(cut.error()));
    }
}

void TestSoundDecode::waveformFollowsTheSound()
{
    // Half a second of silence then half a second of sine.
    QByteArray wav = sineWav(1.0);
    std::fill(wav.begin() + 44, wav.begin() + 44 + 44100, '\0');
    auto sound = decodeSound(wav);
    QVERIFY(sound);
    const Waveform w = computeWaveform(*sound);
    QCOMPARE(qint64(w.peaks.size()), qint64(kWaveformBucketsPerSecond));
    QVERIFY(w.peakBetween(0.0, 0.45) < 0.01f);
    QVERIFY(w.peakBetween(0.55, 1.0) > 0.3f);
    QCOMPARE(w.peakBetween(5.0, 6.0), 0.0f);
}

void TestSoundDecode::mixesClipsAtTheirStartAndVolume()
{
    auto decoded = decodeSound(sineWav(0.5));
    QVERIFY(decoded);
    const auto sound = std::make_shared<const DecodedSound>(std::move(*decoded));
    const SoundLookup lookup = [&](Id) { return sound; };
    std::vector<SoundClip> clips(2);
    clips[0].id = 1;
    clips[0].start = 12; // 12 ticks at 24 fps: 0.5 s
    clips[1].id = 2;
    clips[1].start = 0;
    clips[1].volume = 0.5;
    const qint64 n = kSoundRate; // one second
    std::vector<float> mix(std::size_t(n) * 2, 0.0f);
    mixSoundtrack(clips, lookup, 24, 0, n, mix.data());
    const auto peak = [&](qint64 from, qint64 to) {
        float p = 0.0f;
        for (qint64 i = from * 2; i < to * 2; ++i)
            p = std::max(p, std::abs(mix[std::size_t(i)]));
        return p;
    };
    const float full = peak(n / 2 + 100, n - 100);
    const float half = peak(100, n / 2 - 100);
    QVERIFY(std::abs(half * 2 - full) < 0.01f);
    clips[0].muted = true;
    std::fill(mix.begin(), mix.end(), 0.0f);
    mixSoundtrack(clips, lookup, 24, 0, n, mix.data());
    QCOMPARE(peak(n / 2 + 100, n), 0.0f);
    QVERIFY(soundtrackSoundsIn(clips, lookup, 24, 0, 100));
    QVERIFY(!soundtrackSoundsIn(clips, lookup, 24, n, 100));
    // Loud clips are clipped, never past full scale.
    clips[0].muted = false;
    clips[0].volume = clips[1].volume = kMaxSoundVolume;
    clips[0].start = 0;
    std::fill(mix.begin(), mix.end(), 0.0f);
    mixSoundtrack(clips, lookup, 24, 0, n, mix.data());
    QCOMPARE(peak(0, n), 1.0f);
    const QByteArray wav = mixToWav(clips, lookup, 24, kSoundRate / 4, kSoundRate / 2);
    QCOMPARE(wav.size(), 44 + kSoundRate / 2 * 4);
    auto back = decodeSound(wav);
    QVERIFY(back);
    QVERIFY(std::abs(back->seconds() - 0.5) < 0.001);
}

void TestSoundDecode::cacheDecodesOffTheGuiThread()
{
    Document doc;
    const Id good = importClip(doc, sineWav(0.5), QStringLiteral("good.wav"));
    const Id bad = importClip(doc, QByteArray(5000, 'x'), QStringLiteral("bad.wav"));
    SoundCache cache(&doc);
    QSignalSpy ready(&cache, &SoundCache::soundReady);
    QSignalSpy failed(&cache, &SoundCache::soundFailed);
    QVERIFY(cache.isPending(good) || cache.sound(good));
    QTRY_COMPARE(ready.count() + failed.count(), 2);
    QVERIFY(cache.sound(good));
    QVERIFY(cache.waveform(good) && !cache.waveform(good)->peaks.empty());
    QVERIFY(!cache.sound(bad));
    QVERIFY(!cache.error(bad).isEmpty());
    // A clip imported later is decoded as it arrives; a cache going away mid-work waits for it.
    const Id later = importClip(doc, sineWav(3.0), QStringLiteral("later.wav"));
    QVERIFY(cache.isPending(later));
    auto *gone = new SoundCache(&doc);
    delete gone;
    cache.waitForIdle();
    QVERIFY(cache.sound(later));
    // A new document drops what the old one's clips needed.
    doc.reset(std::vector<Frame>{}, DocumentSettings(), 1);
    QVERIFY(!cache.sound(good) && !cache.sound(later));
}

QTEST_GUILESS_MAIN(TestSoundDecode)
// Issue 47: a 7 KB WAV at 1 Hz announces an hour and, resampled to 48 kHz, asked for 5 GB.
void TestSoundDecode::refusesRatesOutsideTheRange()
{
    QElapsedTimer clock;
    clock.start();
    const QByteArray bomb = sineWav(3500, 1, 0.1);
    QVERIFY(bomb.size() < 8000);
    finbook::Expected<DecodedSound, QString> slow = finbook::unexpected(QString());
    const long rise = peakRiseMiB([&] { slow = decodeSound(bomb); });
    QVERIFY(!slow);
    QVERIFY2(slow.error().contains(QStringLiteral("1 Hz")), qPrintable(slow.error()));
    auto fast = decodeSound(sineWav(0.01, 400000));
    QVERIFY(!fast);
    QVERIFY2(fast.error().contains(QStringLiteral("400000 Hz")), qPrintable(fast.error()));
    auto lowest = decodeSound(sineWav(0.5, kMinSoundSourceRate));
    QVERIFY2(lowest, lowest ? "" : qPrintable(lowest.error()));
    qInfo("1 Hz WAV of %lld bytes refused in %lld ms, peak rose %ld MiB", qint64(bomb.size()),
          clock.elapsed(), rise);
    QVERIFY(rise < 100);
    QVERIFY(clock.elapsed() < 5000); // generous: it took 24 s and 5 GB
}

// Issue 47: a 655 KB FLAC of 59 minutes of silence decoded to 2.7 GB.
void TestSoundDecode::refusesMoreSoundThanItsBytesHold()
{
    QTemporaryDir dir;
    const QByteArray flac = ffmpegSilence(dir, QStringLiteral("silence.flac"), 3540);
    if (flac.isEmpty())
        QSKIP("no ffmpeg to make the FLAC");
    QVERIFY(flac.size() < 2 << 20);
    QElapsedTimer clock;
    clock.start();
    finbook::Expected<DecodedSound, QString> sound = finbook::unexpected(QString());
    const long rise = peakRiseMiB([&] { sound = decodeSound(flac); });
    qInfo("59 min FLAC of %lld bytes: %s in %lld ms, peak rose %ld MiB", qint64(flac.size()),
          sound ? "decoded" : "refused", clock.elapsed(), rise);
    QVERIFY(!sound);
    QVERIFY2(sound.error().contains(QStringLiteral("KB")), qPrintable(sound.error()));
    // What it may decode to: a minute plus what its bytes pay for (far below 59 minutes).
    QVERIFY(soundSecondsAllowed(flac.size()) < 600);
    QVERIFY(rise < 300);
    QVERIFY(clock.elapsed() < 5000);
    // An export needs the sound under its frames only, and gets it whatever follows.
    SoundDecodeLimits first;
    first.wantedFrames = 2 * kSoundRate;
    auto head = decodeSound(flac, nullptr, first);
    QVERIFY2(head, head ? "" : qPrintable(head.error()));
    QCOMPARE(head->frames(), qint64(2 * kSoundRate));
    // A real hour fits: what an hour of 24 kbit/s sound weighs is allowed an hour.
    QCOMPARE(soundSecondsAllowed(3600 * kMinSoundBytesPerSecond), kMaxSoundSeconds);
}

// 256 tiny clips must not each take a clip's allowance: the soundtrack has one budget.
void TestSoundDecode::soundtrackSharesOneBudget()
{
    QTemporaryDir dir;
    const QByteArray flac = ffmpegSilence(dir, QStringLiteral("short.flac"), 50);
    if (flac.isEmpty())
        QSKIP("no ffmpeg to make the FLAC");
    QVERIFY(decodeSound(flac)); // alone, each fits
    Document doc;
    std::vector<Id> ids;
    for (int i = 0; i < 4; ++i)
        ids.push_back(importClip(doc, flac, QStringLiteral("s%1.flac").arg(i)));
    SoundCache cache(&doc);
    QSignalSpy ready(&cache, &SoundCache::soundReady);
    QSignalSpy failed(&cache, &SoundCache::soundFailed);
    QTRY_COMPARE(ready.count() + failed.count(), 4);
    QCOMPARE(ready.count(), 1); // 50 s of the 60 + (4 × bytes) / 3000 s allowed
    QCOMPARE(failed.count(), 3);
    const QString why = failed.first().at(1).toString();
    QVERIFY2(why.contains(QStringLiteral("other clips")), qPrintable(why));
}

#include "tst_sound_decode.moc"
