// The phones of speech and their timing (issue 49), for lip sync: recognised by PocketSphinx
// (the engine Rhubarb Lip Sync is built on) with its US English models, constrained by the
// dialogue when the animator types it; and, for when those models are not installed, mouth
// shapes from loudness alone.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/lipsync/mouth_shape.h>

#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace finbook::model::lipsync {

// Mono samples in [-1, 1].
struct SpeechAudio {
    std::vector<float> samples;
    int sampleRate = 16000;
};

// The rate the acoustic model was trained at.
constexpr int kRecognizerSampleRate = 16000;

// `audio` at `rate` Hz through a windowed-sinc low-pass below the lower rate's Nyquist frequency
// (to 16 kHz: flat to 6 kHz, -3 dB at 7 kHz, more than 75 dB down from 8 kHz on). Empty when
// the input is empty or a rate is not positive.
SpeechAudio resampled(const SpeechAudio &audio, int rate);

enum class SpeechErrorKind {
    ModelMissing, // the speech models are not installed: fall back to loudnessCues()
    Damaged,      // no usable sound (empty, too short, not finite, a bad rate)
    Silent,       // nothing above the noise floor
    Canceled,     // the progress callback returned false
    Failed,       // the recogniser failed (the message says how)
};

struct SpeechError {
    SpeechErrorKind kind = SpeechErrorKind::Failed;
    QString message; // translated, a sentence for the user
};

struct RecognizedSpeech {
    // From the clip's start to its end without gaps; "SIL" where no one speaks.
    std::vector<TimedPhone> phones;
    // Dialogue words the pronunciation dictionary lacks: spelt by letter-to-sound rules, which
    // may misplace a mouth shape or two (the animator may want to respell them).
    QStringList unknownWords;
    // False when no dialogue was given, or when it did not match the sound (`note` says so) and
    // the phones were recognised without it.
    bool followedDialogue = false;
    QString note; // translated, for the user; empty when all went as asked
};

// Called now and then with the share done (0 to 1); returning false cancels.
using SpeechProgress = std::function<bool(double progress)>;

// The phones spoken in `audio` (any rate; resampled to 16 kHz). With `dialogue` (the words
// spoken, as written: punctuation marks where pauses may fall, numbers are read out) the phones
// are the dialogue's, aligned to the sound; without, they are recognised phone by phone. CPU
// time about 3 % of the clip's duration with a dialogue, 7 % without (finbook-bench lipsync):
// call it from a worker thread; calls may run on several threads at once. `progress` may be
// empty; once it returns false, it is not called again.
Expected<RecognizedSpeech, SpeechError>
recognizePhones(const SpeechAudio &audio, const QString &dialogue, const SpeechProgress &progress);

// Where the models are looked for: $FINBOOK_SPEECH_MODEL_DIR, else the en-us folder of the
// PocketSphinx package's model directory. It holds en-us/ (the acoustic model),
// cmudict-en-us.dict and en-us-phone.lm.bin.
QString speechModelDir();

// The fallback without a recogniser: a cue per change of loudness at `fps` frames per second,
// X where it is silent, B half open, D open, measured against the clip's own loudness range.
// Empty for an empty clip or a non-positive fps.
std::vector<MouthCue> loudnessCues(const SpeechAudio &audio, double fps);

} // namespace finbook::model::lipsync
