// Lip sync's timing rules (issue 49): phones give Rhubarb's shapes, closures lead the sound,
// no shape but a closure is shorter than two frames, big jumps get tweens where there is room,
// silences rest the mouth unless they are short, and frames show the shape that covers them.
#include <finbook/model/lipsync/mouth_cues.h>

#include <QtTest>

#include <cmath>
#include <random>

using namespace finbook::model::lipsync;

Q_DECLARE_METATYPE(finbook::model::lipsync::MouthShape)

class TestLipSyncRules : public QObject {
    Q_OBJECT

private slots:
    void lettersNameTheNineShapes();
    void aQuickVowelAfterAnMStillOpens();
    void phonesGiveRhubarbsShapes_data();
    void phonesGiveRhubarbsShapes();
    void diphthongsShowTwoShapes();
    void consonantsTakeTheShapeOfTheirVowel();
    void closuresStartBeforeTheSound_data();
    void closuresStartBeforeTheSound();
    void noShapeButAClosureIsShorterThanTwoFrames();
    void bigJumpsGetTweensWhereThereIsRoom();
    void silencesRestTheMouth();
    void shortPausesInsideSpeechDoNotRest();
    void damagedPhonesAreLeftOut();
    void normalizedCuesAreSortedWithoutRepeats();
    void framesShowTheShapeThatCoversThemMost();
    void aClosureInsideAFrameWinsIt();
    void framesWithoutCuesRest();
};

namespace {

constexpr double kFps = 24.0;

// The shape the cues show at `seconds` (X before the first).
MouthShape shapeAt(const std::vector<MouthCue> &cues, double seconds)
{
    MouthShape shape = MouthShape::X;
    for (const MouthCue &cue : cues) {
        if (cue.start > seconds)
            break;
        shape = cue.shape;
    }
    return shape;
}

QString letters(const std::vector<MouthCue> &cues)
{
    QString out;
    for (const MouthCue &cue : cues)
        out += mouthShapeLetter(cue.shape);
    return out;
}

QString described(const std::vector<MouthCue> &cues)
{
    QStringList parts;
    for (const MouthCue &cue : cues)
        parts << QStringLiteral("%1@%2").arg(mouthShapeLetter(cue.shape)).arg(cue.start, 0, 'f', 3);
    return parts.join(u' ');
}

// `phone` from `start` to `end` between half a second of silence on each side.
std::vector<TimedPhone> alone(const QString &phone, double seconds)
{
    return {{QStringLiteral("SIL"), 0.0, 0.5},
            {phone, 0.5, 0.5 + seconds},
            {QStringLiteral("SIL"), 0.5 + seconds, 1.5 + seconds}};
}

void verifyWellFormed(const std::vector<MouthCue> &cues)
{
    QVERIFY(!cues.empty());
    QCOMPARE(cues.front().start, 0.0);
    QCOMPARE(cues.back().shape, MouthShape::X);
    for (size_t i = 1; i < cues.size(); ++i) {
        QVERIFY2(cues[i].start > cues[i - 1].start, qPrintable(described(cues)));
        QVERIFY2(cues[i].shape != cues[i - 1].shape, qPrintable(described(cues)));
    }
}

} // namespace

void TestLipSyncRules::lettersNameTheNineShapes()
{
    const QString all = QStringLiteral("ABCDEFGHX");
    for (int i = 0; i < kMouthShapeCount; ++i) {
        const auto shape = static_cast<MouthShape>(i);
        QCOMPARE(mouthShapeLetter(shape), all[i]);
        QCOMPARE(mouthShapeFromLetter(all[i]), std::optional(shape));
        QCOMPARE(mouthShapeFromLetter(all[i].toLower()), std::optional(shape));
    }
    for (const QChar c : QStringLiteral("IJZ1 -Ⓐ"))
        QCOMPARE(mouthShapeFromLetter(c), std::nullopt);
}

void TestLipSyncRules::phonesGiveRhubarbsShapes_data()
{
    QTest::addColumn<QString>("phone");
    QTest::addColumn<double>("seconds");
    QTest::addColumn<MouthShape>("shape");
    const auto row = [](const char *phone, double seconds, MouthShape shape) {
        QTest::addRow("%s %.2f", phone, seconds) << QString::fromLatin1(phone) << seconds << shape;
    };
    using enum MouthShape;
    row("M", 0.3, A);
    row("AA", 0.3, D);
    row("AA1", 0.3, D); // stress digits are dropped
    row("aa", 0.3, D);
    row("AE", 0.3, C);
    row("EH", 0.3, C);
    row("AH", 0.1, C);
    row("AH", 0.3, D);
    row("IH", 0.3, B);
    row("IY", 0.3, B);
    row("AO", 0.3, E);
    row("ER", 0.3, E);
    row("UW", 0.3, F);
    row("UH", 0.3, F);
    row("W", 0.3, F);
    row("F", 0.3, G);
    row("V", 0.3, G);
    row("L", 0.3, H);
    row("S", 0.3, B);
    row("T", 0.3, B);
    row("K", 0.3, B);
    row("NG", 0.3, B);
    row("ZZ", 0.3, B); // not ARPAbet: most consonants are B
    row("SIL", 0.3, X);
}

void TestLipSyncRules::phonesGiveRhubarbsShapes()
{
    QFETCH(QString, phone);
    QFETCH(double, seconds);
    QFETCH(MouthShape, shape);
    const std::vector<MouthCue> cues = mouthCuesFromPhones(alone(phone, seconds), kFps);
    verifyWellFormed(cues);
    QCOMPARE(shapeAt(cues, 0.25), MouthShape::X);
    QCOMPARE(shapeAt(cues, 0.5 + seconds / 2), shape);
    QCOMPARE(shapeAt(cues, 1.0 + seconds), MouthShape::X);
}

void TestLipSyncRules::diphthongsShowTwoShapes()
{
    using enum MouthShape;
    const std::vector<MouthCue> ow = mouthCuesFromPhones(alone(QStringLiteral("OW"), 0.4), kFps);
    QCOMPARE(shapeAt(ow, 0.6), E);
    QCOMPARE(shapeAt(ow, 0.85), F);
    const std::vector<MouthCue> ay = mouthCuesFromPhones(alone(QStringLiteral("AY"), 0.4), kFps);
    QCOMPARE(shapeAt(ay, 0.6), D); // a long AY opens wide, then closes to B
    QCOMPARE(shapeAt(ay, 0.85), B);
}

// Anticipation: a consonant that may take several shapes takes the coming vowel's.
void TestLipSyncRules::consonantsTakeTheShapeOfTheirVowel()
{
    const auto cuesFor = [](const char *vowel) {
        return mouthCuesFromPhones({{QStringLiteral("SIL"), 0.0, 0.5},
                                    {QStringLiteral("S"), 0.5, 0.62},
                                    {QString::fromLatin1(vowel), 0.62, 0.9},
                                    {QStringLiteral("SIL"), 0.9, 1.6}},
                                   kFps);
    };
    QCOMPARE(shapeAt(cuesFor("UW"), 0.56), MouthShape::F); // "sue"
    QCOMPARE(shapeAt(cuesFor("IY"), 0.56), MouthShape::B); // "see"
    QCOMPARE(shapeAt(cuesFor("AA"), 0.56), MouthShape::B); // D is not a shape of S
}

void TestLipSyncRules::closuresStartBeforeTheSound_data()
{
    QTest::addColumn<QString>("phone");
    QTest::addColumn<bool>("heardClosed");
    QTest::newRow("M") << QStringLiteral("M") << true;
    QTest::newRow("B") << QStringLiteral("B") << false;
    QTest::newRow("P") << QStringLiteral("P") << false;
}

void TestLipSyncRules::closuresStartBeforeTheSound()
{
    QFETCH(QString, phone);
    QFETCH(bool, heardClosed);
    const double sound = 0.6;
    const std::vector<TimedPhone> phones = {{QStringLiteral("SIL"), 0.0, 0.3},
                                            {QStringLiteral("AA"), 0.3, sound},
                                            {phone, sound, 0.7},
                                            {QStringLiteral("AA"), 0.7, 1.0},
                                            {QStringLiteral("SIL"), 1.0, 2.0}};
    const std::vector<MouthCue> cues = mouthCuesFromPhones(phones, kFps);
    verifyWellFormed(cues);
    const auto closure = std::find_if(cues.begin(), cues.end(),
                                      [](const MouthCue &c) { return c.shape == MouthShape::A; });
    QVERIFY2(closure != cues.end(), qPrintable(described(cues)));
    QVERIFY2(closure->start < sound - 0.03, qPrintable(described(cues)));
    QVERIFY2(closure->start >= sound - 0.12 - 1e-9, qPrintable(described(cues)));
    QCOMPARE(shapeAt(cues, sound - 0.01), MouthShape::A);
    // M is heard with closed lips; B and P as the lips part for the vowel.
    QCOMPARE(shapeAt(cues, 0.65), heardClosed ? MouthShape::A : MouthShape::D);
    // On frames the lips are shut on the frame before the sound.
    const std::vector<MouthShape> frames = mouthShapesPerFrame(cues, kFps, 48);
    QCOMPARE(frames[size_t(std::floor((sound - 1e-6) * kFps))], MouthShape::A);
}

// Seeded random speech of every kind of phone, many of them shorter than two frames.
void TestLipSyncRules::noShapeButAClosureIsShorterThanTwoFrames()
{
    const QStringList symbols = {
        QStringLiteral("AA"), QStringLiteral("AE"), QStringLiteral("AH"), QStringLiteral("AO"),
        QStringLiteral("AW"), QStringLiteral("AY"), QStringLiteral("EH"), QStringLiteral("ER"),
        QStringLiteral("EY"), QStringLiteral("IH"), QStringLiteral("IY"), QStringLiteral("OW"),
        QStringLiteral("OY"), QStringLiteral("UH"), QStringLiteral("UW"), QStringLiteral("B"),
        QStringLiteral("CH"), QStringLiteral("D"),  QStringLiteral("DH"), QStringLiteral("F"),
        QStringLiteral("G"),  QStringLiteral("HH"), QStringLiteral("JH"), QStringLiteral("K"),
        QStringLiteral("L"),  QStringLiteral("M"),  QStringLiteral("N"),  QStringLiteral("NG"),
        QStringLiteral("P"),  QStringLiteral("R"),  QStringLiteral("S"),  QStringLiteral("SH"),
        QStringLiteral("T"),  QStringLiteral("TH"), QStringLiteral("V"),  QStringLiteral("W"),
        QStringLiteral("Y"),  QStringLiteral("Z"),  QStringLiteral("ZH"), QStringLiteral("SIL")};
    std::mt19937 random(49);
    std::uniform_int_distribution<qsizetype> pick(0, symbols.size() - 1);
    std::uniform_real_distribution<double> length(0.005, 0.3);
    int shortPhones = 0;
    int closures = 0;
    for (const double fps : {12.0, 24.0, 25.0, 30.0, 60.0}) {
        for (int run = 0; run < 60; ++run) {
            std::vector<TimedPhone> phones;
            double t = 0.2;
            for (int i = 0; i < 40; ++i) {
                const double seconds = length(random);
                phones.push_back({symbols[pick(random)], t, t + seconds});
                shortPhones += seconds < 2.0 / fps ? 1 : 0;
                t += seconds;
            }
            const std::vector<MouthCue> cues = mouthCuesFromPhones(phones, fps);
            verifyWellFormed(cues);
            // The mouth rests when speech ends, or one tween later (D→X closes through C).
            QVERIFY(cues.back().start <= t + std::max(0.08, 2.0 / fps) + 1e-9);
            for (size_t i = 0; i + 1 < cues.size(); ++i) {
                const double seconds = cues[i + 1].start - cues[i].start;
                QVERIFY2(cues[i].shape == MouthShape::A || seconds >= 2.0 / fps - 1e-9,
                         qPrintable(QStringLiteral("%1 fps: %2").arg(fps).arg(described(cues))));
            }
            // Every M, B and P shows a closed mouth on the frame just before it is heard.
            const std::vector<MouthShape> frames = mouthShapesPerFrame(cues, fps, int(t * fps) + 2);
            for (const TimedPhone &phone : phones) {
                if (phone.phone != u"M" && phone.phone != u"B" && phone.phone != u"P")
                    continue;
                ++closures;
                QCOMPARE(shapeAt(cues, phone.start - 1e-6), MouthShape::A);
                QCOMPARE(frames[size_t(std::floor((phone.start - 1e-6) * fps))], MouthShape::A);
            }
        }
    }
    QVERIFY(shortPhones > 1000); // the rule had work to do
    QVERIFY(closures > 500);
}

void TestLipSyncRules::bigJumpsGetTweensWhereThereIsRoom()
{
    const auto cuesFor = [](double vowelSeconds, const char *next) {
        const double end = 0.5 + vowelSeconds;
        return mouthCuesFromPhones({{QStringLiteral("SIL"), 0.0, 0.5},
                                    {QStringLiteral("AA"), 0.5, end},
                                    {QString::fromLatin1(next), end, end + 0.5},
                                    {QStringLiteral("SIL"), end + 0.5, end + 1.5}},
                                   kFps);
    };
    // D→A: C closes the wide mouth at the end of the D, for two frames at least.
    const std::vector<MouthCue> roomy = cuesFor(0.5, "M");
    QVERIFY2(letters(roomy).contains(u"DCA"), qPrintable(described(roomy)));
    const auto tween = std::find_if(roomy.begin(), roomy.end(),
                                    [](const MouthCue &c) { return c.shape == MouthShape::C; });
    QVERIFY(std::next(tween)->start - tween->start >= 2.0 / kFps - 1e-9);
    // A short D leaves no room for a two-frame tween.
    const std::vector<MouthCue> tight = cuesFor(0.2, "M");
    QVERIFY2(letters(tight).contains(u"DA"), qPrintable(described(tight)));
    // D→F: E across the change; D→X: C at the start of the rest.
    const std::vector<MouthCue> pucker = cuesFor(0.5, "UW");
    QVERIFY2(letters(pucker).contains(u"DEF"), qPrintable(described(pucker)));
    const std::vector<MouthCue> rest = cuesFor(0.5, "SIL");
    QVERIFY2(letters(rest) == u"XDCX", qPrintable(described(rest)));
    QCOMPARE(rest[2].start, 1.0);
    // No tween where the jump is small.
    const std::vector<MouthCue> small = cuesFor(0.5, "EH");
    QVERIFY2(letters(small) == u"XDCX", qPrintable(described(small)));
    QCOMPARE(small[2].start, 1.0); // that C is the EH itself, from its start
}

void TestLipSyncRules::silencesRestTheMouth()
{
    QCOMPARE(mouthCuesFromPhones({}, kFps), (std::vector<MouthCue>{{0.0, MouthShape::X}}));
    QCOMPARE(mouthCuesFromPhones({{QStringLiteral("SIL"), 0.0, 2.0}}, kFps),
             (std::vector<MouthCue>{{0.0, MouthShape::X}}));
    // Before, between (long) and after speech, whether silence is a phone or a gap.
    for (const bool gap : {false, true}) {
        std::vector<TimedPhone> phones = {{QStringLiteral("AA"), 0.4, 0.7},
                                          {QStringLiteral("SIL"), 0.7, 1.3},
                                          {QStringLiteral("AA"), 1.3, 1.6}};
        if (gap)
            phones.erase(phones.begin() + 1);
        const std::vector<MouthCue> cues = mouthCuesFromPhones(phones, kFps);
        verifyWellFormed(cues);
        QCOMPARE(shapeAt(cues, 0.2), MouthShape::X);
        QCOMPARE(shapeAt(cues, 1.1), MouthShape::X);
        QCOMPARE(shapeAt(cues, 1.75), MouthShape::X);
        QCOMPARE(shapeAt(cues, 0.55), MouthShape::D);
        QCOMPARE(shapeAt(cues, 1.45), MouthShape::D);
    }
}

void TestLipSyncRules::shortPausesInsideSpeechDoNotRest()
{
    const auto cuesWithPause = [](double pause) {
        return mouthCuesFromPhones({{QStringLiteral("AA"), 0.4, 0.8},
                                    {QStringLiteral("SIL"), 0.8, 0.8 + pause},
                                    {QStringLiteral("AA"), 0.8 + pause, 1.2 + pause}},
                                   kFps);
    };
    // Under 0.12 s the shape holds; up to 0.35 s it relaxes (D to C); beyond it rests.
    const std::vector<MouthCue> held = cuesWithPause(0.1);
    QVERIFY2(letters(held) == u"XDCX", qPrintable(described(held))); // C: the tween to rest
    QCOMPARE(shapeAt(held, 0.85), MouthShape::D);
    const std::vector<MouthCue> relaxed = cuesWithPause(0.25);
    QCOMPARE(shapeAt(relaxed, 0.93), MouthShape::C);
    QVERIFY2(!letters(relaxed).mid(1).chopped(1).contains(u'X'), qPrintable(described(relaxed)));
    const std::vector<MouthCue> rested = cuesWithPause(0.5);
    QCOMPARE(shapeAt(rested, 1.05), MouthShape::X);
}

void TestLipSyncRules::damagedPhonesAreLeftOut()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<TimedPhone> clean = {{QStringLiteral("AA"), 0.4, 0.8},
                                           {QStringLiteral("M"), 0.8, 0.9},
                                           {QStringLiteral("UW"), 0.9, 1.3}};
    std::vector<TimedPhone> damaged = {clean[2], clean[0], clean[1]}; // out of order
    damaged.push_back({QStringLiteral("AA"), nan, 1.0});
    damaged.push_back({QStringLiteral("AA"), 0.5, inf});
    damaged.push_back({QStringLiteral("AA"), -0.5, 0.1});
    damaged.push_back({QStringLiteral("AA"), 0.6, 0.6});
    damaged.push_back({QStringLiteral("AA"), 0.7, 0.3});
    damaged.push_back({QStringLiteral("L"), 0.85, 0.88}); // inside the M: nothing is left of it
    const std::vector<MouthCue> expected = mouthCuesFromPhones(clean, kFps);
    QCOMPARE(mouthCuesFromPhones(damaged, kFps), expected);
    // A bad frame rate leaves out the frame rules but still gives the shapes.
    const std::vector<MouthCue> anyRate = mouthCuesFromPhones(clean, nan);
    verifyWellFormed(anyRate);
    QCOMPARE(shapeAt(anyRate, 0.6), MouthShape::D);
}

void TestLipSyncRules::normalizedCuesAreSortedWithoutRepeats()
{
    using enum MouthShape;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<MouthCue> cues = normalizedCues(
        {{0.5, D}, {0.0, X}, {0.2, B}, {0.3, B}, {nan, C}, {0.5, C}, {0.7, C}, {0.9, X}});
    QCOMPARE(cues, (std::vector<MouthCue>{{0.0, X}, {0.2, B}, {0.5, C}, {0.9, X}}));
}

void TestLipSyncRules::framesShowTheShapeThatCoversThemMost()
{
    using enum MouthShape;
    QCOMPARE(mouthShapesPerFrame({{0.0, X}, {0.1, D}, {0.3, X}}, 10.0, 5),
             (std::vector<MouthShape>{X, D, D, X, X}));
    QCOMPARE(mouthShapesPerFrame({{0.0, B}, {0.06, D}}, 10.0, 2), (std::vector<MouthShape>{B, D}));
    QCOMPARE(mouthShapesPerFrame({{0.0, B}, {0.04, D}}, 10.0, 2), (std::vector<MouthShape>{D, D}));
    // A tie goes to the later shape; two pieces of one shape add up.
    QCOMPARE(mouthShapesPerFrame({{0.0, B}, {0.05, D}}, 10.0, 1), (std::vector<MouthShape>{D}));
    QCOMPARE(mouthShapesPerFrame({{0.0, B}, {0.03, D}, {0.06, B}, {0.08, C}}, 10.0, 1),
             (std::vector<MouthShape>{B}));
    // Unsorted cues are read in time order.
    QCOMPARE(mouthShapesPerFrame({{0.3, X}, {0.1, D}, {0.0, X}}, 10.0, 5),
             (std::vector<MouthShape>{X, D, D, X, X}));
}

void TestLipSyncRules::aClosureInsideAFrameWinsIt()
{
    using enum MouthShape;
    QCOMPARE(mouthShapesPerFrame({{0.0, D}, {0.12, A}, {0.14, D}}, 10.0, 3),
             (std::vector<MouthShape>{D, A, D}));
    // Another short shape does not win that way.
    QCOMPARE(mouthShapesPerFrame({{0.0, D}, {0.12, G}, {0.14, D}}, 10.0, 3),
             (std::vector<MouthShape>{D, D, D}));
}

void TestLipSyncRules::framesWithoutCuesRest()
{
    using enum MouthShape;
    QCOMPARE(mouthShapesPerFrame({}, 10.0, 3), (std::vector<MouthShape>{X, X, X}));
    QCOMPARE(mouthShapesPerFrame({{0.0, D}}, 10.0, 0), std::vector<MouthShape>{});
    QCOMPARE(mouthShapesPerFrame({{0.0, D}}, 10.0, -4), std::vector<MouthShape>{});
    QCOMPARE(mouthShapesPerFrame({{0.0, D}}, 0.0, 2), (std::vector<MouthShape>{X, X}));
    QCOMPARE(mouthShapesPerFrame({{0.0, D}}, std::nan(""), 2), (std::vector<MouthShape>{X, X}));
    // Before the first cue the mouth rests.
    QCOMPARE(mouthShapesPerFrame({{0.27, D}}, 10.0, 4), (std::vector<MouthShape>{X, X, X, D}));
}

// "mom" spoken quickly: the vowel (70 ms) is shorter than two frames at 24 fps. It takes the time
// it lacks from the M's closure after the M is heard, so the mouth opens between the closures
// instead of staying shut, and both M are still closed just before they are heard.
void TestLipSyncRules::aQuickVowelAfterAnMStillOpens()
{
    const std::vector<TimedPhone> mom = {{QStringLiteral("SIL"), 0.0, 0.3},
                                         {QStringLiteral("M"), 0.3, 0.4},
                                         {QStringLiteral("AA"), 0.4, 0.47},
                                         {QStringLiteral("M"), 0.47, 0.55},
                                         {QStringLiteral("SIL"), 0.55, 1.0}};
    const double fps = 24.0;
    const std::vector<MouthCue> cues = mouthCuesFromPhones(mom, fps);
    const auto open = std::find_if(cues.begin(), cues.end(),
                                   [](const MouthCue &c) { return c.shape == MouthShape::D; });
    QVERIFY(open != cues.end());
    QVERIFY(open + 1 != cues.end());
    QVERIFY((open + 1)->start - open->start >= 2.0 / fps - 1e-9);
    const std::vector<MouthShape> frames = mouthShapesPerFrame(cues, fps, 24);
    QCOMPARE(frames[std::size_t(std::floor((0.3 - 1e-6) * fps))], MouthShape::A);
    QCOMPARE(frames[std::size_t(std::floor((0.47 - 1e-6) * fps))], MouthShape::A);
    QVERIFY(std::count(frames.begin(), frames.end(), MouthShape::D) >= 1);
}

QTEST_APPLESS_MAIN(TestLipSyncRules)
#include "tst_lipsync_rules.moc"
