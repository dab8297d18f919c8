// The rules are listed in mouth_cues.h; the reasons for each step are given where it is done.
#include <finbook/model/lipsync/mouth_cues.h>

#include <QHash>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace finbook::model::lipsync {

QChar mouthShapeLetter(MouthShape shape)
{
    static constexpr char kLetters[] = "ABCDEFGHX";
    const auto index = static_cast<int>(shape);
    return index < kMouthShapeCount ? QChar::fromLatin1(kLetters[index]) : QChar(u'X');
}

std::optional<MouthShape> mouthShapeFromLetter(QChar letter)
{
    const char16_t c = letter.toUpper().unicode();
    if (c >= u'A' && c <= u'H')
        return static_cast<MouthShape>(c - u'A');
    if (c == u'X')
        return MouthShape::X;
    return std::nullopt;
}

namespace {

// Times closer than this are the same time (seconds are far coarser than a microsecond).
constexpr double kEpsilon = 1e-9;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Rhubarb's timings, in seconds.
constexpr double kAnticipation = 0.20;   // how far ahead a consonant looks for its vowel
constexpr int kAnticipationPhones = 8;   // ...and over how many phones (bounds the look-ahead)
constexpr double kDiphthongSplit = 0.6;  // the first shape's share of a diphthong
constexpr double kMinClosureLead = 0.04; // the closed lips before M B P
constexpr double kMaxClosureLead = 0.12;
constexpr double kHoldPause = 0.12;  // shorter pauses hold the shape
constexpr double kRelaxPause = 0.35; // pauses up to this relax the mouth, longer ones rest
constexpr double kMinTween = 0.04;
constexpr double kMaxTween = 0.08;

using ShapeMask = quint16;

constexpr ShapeMask bit(MouthShape shape)
{
    return ShapeMask(1u << static_cast<unsigned>(shape));
}

constexpr ShapeMask maskOf(std::initializer_list<MouthShape> shapes)
{
    ShapeMask mask = 0;
    for (const MouthShape shape : shapes)
        mask |= bit(shape);
    return mask;
}

using enum MouthShape;

constexpr ShapeMask kAnyShape = maskOf({A, B, C, D, E, F, G, H});

enum class PhoneKind : quint8 { Silence, Vowel, Consonant };

struct PhoneRule {
    PhoneKind kind = PhoneKind::Consonant;
    ShapeMask allowed = bit(B);      // a single bit: the shape is fixed
    MouthShape first = B;            // the shape when the neighbours do not decide
    std::optional<MouthShape> glide; // a diphthong's second shape
    bool closesLips = false;         // M B P
};

PhoneRule vowel(MouthShape shape, std::optional<MouthShape> glide = std::nullopt)
{
    return {PhoneKind::Vowel, bit(shape), shape, glide, false};
}

PhoneRule consonant(MouthShape first, ShapeMask alternatives = 0)
{
    return {PhoneKind::Consonant, ShapeMask(bit(first) | alternatives), first, std::nullopt, false};
}

PhoneRule silence()
{
    return {PhoneKind::Silence, bit(X), X, std::nullopt, false};
}

bool isFixed(ShapeMask mask)
{
    return (mask & (mask - 1)) == 0;
}

// ARPAbet as a recogniser writes it: "aa1" is AA.
QString arpabetSymbol(const QString &phone)
{
    QString symbol = phone.trimmed().toUpper();
    while (!symbol.isEmpty() && symbol.back().isDigit())
        symbol.chop(1);
    return symbol;
}

const QHash<QString, PhoneRule> &fixedRules()
{
    static const QHash<QString, PhoneRule> rules = [] {
        const ShapeMask orF = maskOf({F}); // lips pushed forward when a rounded vowel follows
        return QHash<QString, PhoneRule>{
            {"SIL", silence()},
            {"SP", silence()},
            {"SPN", silence()},
            {"NSN", silence()},
            {"", silence()},
            {"AA", vowel(D)},
            {"AE", vowel(C)},
            {"AO", vowel(E)},
            {"EH", vowel(C)},
            {"IH", vowel(B)},
            {"IY", vowel(B)},
            {"UH", vowel(F)},
            {"UW", vowel(F)},
            {"EY", vowel(C, B)},
            {"OW", vowel(E, F)},
            {"OY", vowel(E, B)},
            {"M", {PhoneKind::Consonant, bit(A), A, std::nullopt, true}},
            // B and P: the closure comes before the sound; the sound is the lips parting.
            {"B", {PhoneKind::Consonant, kAnyShape, B, std::nullopt, true}},
            {"P", {PhoneKind::Consonant, kAnyShape, B, std::nullopt, true}},
            {"HH", consonant(B, kAnyShape)}, // "m-hm": the mouth is shaped by its neighbours
            {"F", consonant(G)},
            {"V", consonant(G)},
            {"L", consonant(H)},
            {"W", consonant(F)},
            {"T", consonant(B, orF)},
            {"D", consonant(B, orF)},
            {"CH", consonant(B, orF)},
            {"JH", consonant(B, orF)},
            {"TH", consonant(B, orF)},
            {"DH", consonant(B, orF)},
            {"S", consonant(B, orF)},
            {"Z", consonant(B, orF)},
            {"SH", consonant(B, orF)},
            {"ZH", consonant(B, orF)},
            {"K", consonant(B, maskOf({C, E, F, H}))},
            {"G", consonant(B, maskOf({C, E, F, H}))},
            {"N", consonant(B, maskOf({C, F, H}))},
            {"NG", consonant(B, maskOf({C, E, F}))},
            {"R", consonant(B, maskOf({E, F}))},
            {"Y", consonant(B, maskOf({C, F}))},
        };
    }();
    return rules;
}

// Longer vowels open wider: these four depend on how long they are heard.
PhoneRule ruleFor(const QString &phone, double seconds)
{
    const QString symbol = arpabetSymbol(phone);
    if (symbol == u"AH")
        return vowel(seconds < 0.20 ? C : D);
    if (symbol == u"ER")
        return vowel(seconds < 0.07 ? C : E);
    if (symbol == u"AW")
        return vowel(seconds < 0.30 ? C : D, E);
    if (symbol == u"AY")
        return vowel(seconds < 0.20 ? C : D, B);
    return fixedRules().value(symbol, consonant(B)); // unknown symbols: most consonants are B
}

struct Phone {
    double start = 0.0;
    double end = 0.0;
    PhoneRule rule;
};

// Rule 1: in time order, without overlaps, the gaps filled with silence from 0 on.
std::vector<Phone> cleanedPhones(const std::vector<TimedPhone> &phones)
{
    std::vector<const TimedPhone *> valid;
    valid.reserve(phones.size());
    for (const TimedPhone &phone : phones) {
        if (std::isfinite(phone.start) && std::isfinite(phone.end) && phone.start >= 0.0 &&
            phone.end > phone.start)
            valid.push_back(&phone);
    }
    std::stable_sort(valid.begin(), valid.end(),
                     [](const TimedPhone *a, const TimedPhone *b) { return a->start < b->start; });
    std::vector<Phone> cleaned;
    cleaned.reserve(valid.size() * 2);
    double cursor = 0.0;
    for (const TimedPhone *phone : valid) {
        double start = std::max(phone->start, cursor);
        if (phone->end - start <= kEpsilon)
            continue;
        if (start - cursor > kEpsilon)
            cleaned.push_back({cursor, start, silence()});
        else
            start = cursor;
        cleaned.push_back({start, phone->end, ruleFor(phone->phone, phone->end - start)});
        cursor = phone->end;
    }
    return cleaned;
}

struct Segment {
    double start = 0.0;
    double end = 0.0;
    MouthShape shape = X;
    bool pause = false; // silence between phones: rule 4 decides its shape
    // A closure: when its M, B or P is heard (the lips must be closed just before); -1 else.
    double heard = -1.0;
    double length() const { return end - start; }
};
using Timeline = std::vector<Segment>;

void append(Timeline &timeline, const Segment &segment)
{
    if (!timeline.empty() && timeline.back().shape == segment.shape &&
        timeline.back().pause == segment.pause) {
        timeline.back().end = segment.end;
        timeline.back().heard = std::max(timeline.back().heard, segment.heard);
        return;
    }
    timeline.push_back(segment);
}

// The shape of the vowel the mouth is already forming for, if one comes within kAnticipation
// with nothing but flexible consonants before it.
std::optional<MouthShape> upcomingVowel(const std::vector<Phone> &phones, size_t index)
{
    const size_t last = std::min(phones.size(), index + 1 + kAnticipationPhones);
    for (size_t j = index + 1; j < last; ++j) {
        const Phone &next = phones[j];
        if (next.start - phones[index].start > kAnticipation ||
            next.rule.kind == PhoneKind::Silence)
            return std::nullopt;
        if (next.rule.kind == PhoneKind::Vowel)
            return next.rule.first;
        if (isFixed(next.rule.allowed))
            return std::nullopt;
    }
    return std::nullopt;
}

// Rule 2 for one phone.
MouthShape chosenShape(const std::vector<Phone> &phones, size_t index, MouthShape previous)
{
    const PhoneRule &rule = phones[index].rule;
    if (isFixed(rule.allowed))
        return rule.first;
    if (const auto next = upcomingVowel(phones, index); next && (rule.allowed & bit(*next)))
        return *next;
    if (rule.allowed & bit(previous))
        return previous;
    return rule.first;
}

// Rule 3: the lips close before the sound is heard, in time taken from the previous shape.
void closeLipsBefore(Timeline &timeline, double soundStart)
{
    if (timeline.empty() || timeline.back().shape == A)
        return;
    Segment &before = timeline.back();
    const double lead = std::min(
        std::clamp(before.length() / 2.0, kMinClosureLead, kMaxClosureLead), before.length());
    before.end -= lead;
    const double closureStart = before.end;
    if (before.length() <= kEpsilon)
        timeline.pop_back();
    append(timeline, {closureStart, soundStart, A, false, soundStart});
}

// Rules 2 and 3.
Timeline roughTimeline(const std::vector<Phone> &phones)
{
    Timeline timeline;
    for (size_t i = 0; i < phones.size(); ++i) {
        const Phone &phone = phones[i];
        if (phone.rule.kind == PhoneKind::Silence) {
            append(timeline, {phone.start, phone.end, X, true});
            continue;
        }
        if (phone.rule.closesLips)
            closeLipsBefore(timeline, phone.start);
        const MouthShape previous = timeline.empty() ? X : timeline.back().shape;
        const MouthShape shape = chosenShape(phones, i, previous);
        if (phone.rule.glide) {
            const double split = phone.start + kDiphthongSplit * (phone.end - phone.start);
            append(timeline, {phone.start, split, shape, false});
            append(timeline, {split, phone.end, *phone.rule.glide, false});
        } else {
            append(timeline, {phone.start, phone.end, shape, false});
        }
    }
    return timeline;
}

MouthShape relaxed(MouthShape shape)
{
    static constexpr std::array<MouthShape, kMouthShapeCount> kRelaxed = {A, B, B, C, C,
                                                                          B, X, B, X};
    return kRelaxed[static_cast<size_t>(shape)];
}

MouthShape pauseShape(MouthShape previous, MouthShape next, double seconds)
{
    if (seconds < kHoldPause)
        return previous;
    if (seconds <= kRelaxPause) {
        // A relaxed shape that is the next shape would look like the next sound came early.
        for (MouthShape current = previous;;) {
            const MouthShape relaxedShape = relaxed(current);
            if (relaxedShape != next)
                return relaxedShape;
            if (relaxedShape == current)
                break;
            current = relaxedShape;
        }
    }
    return X;
}

// Rule 4 (silence at either end stays X).
void animatePauses(Timeline &timeline)
{
    for (size_t i = 1; i + 1 < timeline.size(); ++i) {
        Segment &pause = timeline[i];
        if (pause.pause && !timeline[i - 1].pause && !timeline[i + 1].pause)
            pause.shape = pauseShape(timeline[i - 1].shape, timeline[i + 1].shape, pause.length());
    }
}

Timeline mergedShapes(const Timeline &timeline)
{
    Timeline merged;
    merged.reserve(timeline.size());
    for (Segment segment : timeline) {
        segment.pause = false;
        append(merged, segment);
    }
    return merged;
}

// Rule 5. Shapes are lengthened to the left only: the mouth may lead the sound, never lag. A
// shape too short takes the time from the shape before it: a closure keeps half the minimum,
// any other shape the whole of it.
Timeline withMinimumLengths(Timeline timeline, double minLength)
{
    Timeline out;
    out.reserve(timeline.size());
    for (size_t i = 0; i < timeline.size(); ++i) {
        Segment segment = timeline[i];
        if (!out.empty() && out.back().shape == segment.shape) {
            out.back().end = segment.end;
            out.back().heard = std::max(out.back().heard, segment.heard);
            continue;
        }
        const double missing = minLength - segment.length();
        if (segment.shape == A || missing <= kEpsilon) {
            out.push_back(segment);
            continue;
        }
        const bool previousCanGive = !out.empty() && out.back().shape != A;
        // A closure before it gives time down to half the minimum (an A anywhere in a frame
        // wins it, so it still shows), never the moment its sound is heard: in quick speech
        // ("mom", "maybe") the vowel after an M is shorter than two frames, and dropping it
        // kept the mouth shut.
        const bool closureCanGive =
            !out.empty() && out.back().shape == A &&
            out.back().length() - missing >= minLength / 2 - kEpsilon &&
            out.back().end - missing > std::max(out.back().heard, out.back().start) + kEpsilon;
        if (closureCanGive) {
            out.back().end -= missing;
            segment.start -= missing;
            out.push_back(segment);
        } else if (previousCanGive && out.back().length() - missing >= minLength - kEpsilon) {
            out.back().end -= missing;
            segment.start -= missing;
            out.push_back(segment);
        } else if (previousCanGive) {
            out.back().end = segment.end;
        } else if (i + 1 < timeline.size()) {
            timeline[i + 1].start = segment.start;
        } else if (!out.empty()) {
            out.back().end = segment.end;
        } else {
            out.push_back(segment);
        }
    }
    return out;
}

enum class TweenTiming { Early, Centered, Late };

struct Tween {
    MouthShape shape;
    TweenTiming timing;
};

// Rhubarb's in-betweens. Most go one way only: a mouth pops open but closes gradually.
std::optional<Tween> tweenBetween(MouthShape from, MouthShape to)
{
    using enum TweenTiming;
    struct Rule {
        MouthShape from, to;
        Tween tween;
    };
    static constexpr std::array<Rule, 9> kRules = {{{D, A, {C, Early}},
                                                    {D, B, {C, Centered}},
                                                    {D, G, {C, Early}},
                                                    {D, X, {C, Late}},
                                                    {C, F, {E, Centered}},
                                                    {F, C, {E, Centered}},
                                                    {D, F, {E, Centered}},
                                                    {H, F, {E, Late}},
                                                    {F, H, {E, Early}}}};
    for (const Rule &rule : kRules) {
        if (rule.from == from && rule.to == to)
            return rule.tween;
    }
    return std::nullopt;
}

// Rule 6. A tween takes at most a third of the shape it comes from (a quarter of each across a
// change), so both keep at least twice the tween's length, and the tween at least two frames.
Timeline withTweens(const Timeline &timeline, double minLength)
{
    const double shortest = std::max(kMinTween, minLength);
    const double longest = std::max(kMaxTween, minLength);
    Timeline out;
    out.reserve(timeline.size() * 2);
    for (Segment next : timeline) {
        const std::optional<Tween> tween =
            out.empty() ? std::nullopt : tweenBetween(out.back().shape, next.shape);
        if (!tween) {
            out.push_back(next);
            continue;
        }
        Segment &previous = out.back();
        const double change = previous.end;
        double length = 0.0;
        switch (tween->timing) {
        case TweenTiming::Early:
            length = std::min(previous.length() / 3.0, longest);
            break;
        case TweenTiming::Centered:
            length = std::min({previous.length() / 4.0, next.length() / 4.0, longest});
            break;
        case TweenTiming::Late:
            length = std::min(next.length() / 3.0, longest);
            break;
        }
        if (length < shortest - kEpsilon) {
            out.push_back(next);
            continue;
        }
        const double tweenStart = tween->timing == TweenTiming::Early      ? change - length
                                  : tween->timing == TweenTiming::Centered ? change - length / 2
                                                                           : change;
        previous.end = tweenStart;
        next.start = tweenStart + length;
        out.push_back({tweenStart, next.start, tween->shape, false});
        out.push_back(next);
    }
    return out;
}

} // namespace

std::vector<MouthCue> mouthCuesFromPhones(const std::vector<TimedPhone> &phones, double fps)
{
    const std::vector<Phone> cleaned = cleanedPhones(phones);
    if (cleaned.empty())
        return {MouthCue{0.0, X}};
    Timeline timeline = roughTimeline(cleaned);
    animatePauses(timeline);
    // Rule 7: the mouth rests after speaking; endless, so that rules 5 and 6 can take from it.
    timeline.push_back({cleaned.back().end, kInfinity, X, false});
    const double minLength = std::isfinite(fps) && fps > 0.0 ? 2.0 / fps : 0.0;
    timeline = withTweens(withMinimumLengths(mergedShapes(timeline), minLength), minLength);
    std::vector<MouthCue> cues;
    cues.reserve(timeline.size());
    for (const Segment &segment : timeline)
        cues.push_back({segment.start, segment.shape});
    return normalizedCues(std::move(cues));
}

std::vector<MouthCue> normalizedCues(std::vector<MouthCue> cues)
{
    std::erase_if(cues, [](const MouthCue &cue) { return !std::isfinite(cue.start); });
    std::stable_sort(cues.begin(), cues.end(),
                     [](const MouthCue &a, const MouthCue &b) { return a.start < b.start; });
    std::vector<MouthCue> out;
    out.reserve(cues.size());
    for (const MouthCue &cue : cues) {
        if (!out.empty() && out.back().start == cue.start)
            out.pop_back(); // the later of two cues at one time is the one meant
        if (out.empty() || out.back().shape != cue.shape)
            out.push_back(cue);
    }
    return out;
}

std::vector<MouthShape> mouthShapesPerFrame(const std::vector<MouthCue> &input, double fps,
                                            int frameCount)
{
    std::vector<MouthShape> frames(size_t(std::max(frameCount, 0)), X);
    const std::vector<MouthCue> cues = normalizedCues(input);
    if (cues.empty() || !std::isfinite(fps) || fps <= 0.0)
        return frames;
    size_t current = 0; // the last cue starting at or before the frame, if any
    for (size_t i = 0; i < frames.size(); ++i) {
        const double frameStart = double(i) / fps;
        const double frameEnd = double(i + 1) / fps;
        while (current + 1 < cues.size() && cues[current + 1].start <= frameStart)
            ++current;
        std::array<double, kMouthShapeCount> cover{};
        MouthShape best = X;
        if (cues.front().start > frameStart) // before the first cue the mouth rests
            cover[size_t(X)] = std::min(cues.front().start, frameEnd) - frameStart;
        bool closure = false;
        for (size_t j = current; j < cues.size() && cues[j].start < frameEnd; ++j) {
            const double from = std::max(cues[j].start, frameStart);
            const double to =
                std::min(j + 1 < cues.size() ? cues[j + 1].start : kInfinity, frameEnd);
            if (to <= from)
                continue;
            cover[size_t(cues[j].shape)] += to - from;
            closure = closure || cues[j].shape == A;
            if (cover[size_t(cues[j].shape)] >= cover[size_t(best)])
                best = cues[j].shape;
        }
        frames[i] = closure ? A : best;
    }
    return frames;
}

} // namespace finbook::model::lipsync
