// Mouth shapes and their timing (issue 49): the nine shapes of the Preston Blair chart as
// Rhubarb Lip Sync names them, the phones a recogniser hears, and the cues that say which
// shape the mouth shows from when. Times are seconds from the start of the clip.
#pragma once

#include <QChar>
#include <QString>

#include <optional>
#include <vector>

namespace finbook::model::lipsync {

// A closed M-B-P, B most consonants (slightly open, teeth), C EH-AE (open), D AA (wide open),
// E AO-ER (slightly rounded), F UW-OW-W (puckered), G F-V (teeth on the lower lip), H L (tongue
// up), X rest (idle, between phrases).
enum class MouthShape : quint8 { A = 0, B, C, D, E, F, G, H, X };
constexpr int kMouthShapeCount = 9;

QChar mouthShapeLetter(MouthShape shape);
std::optional<MouthShape> mouthShapeFromLetter(QChar letter); // upper or lower case

// One phone as a recogniser or a synthesiser timed it: an ARPAbet symbol in upper case without
// stress digits ("AA", "M", "TH"), or "SIL" for silence and noise.
struct TimedPhone {
    QString phone;
    double start = 0.0;
    double end = 0.0;
};

// The mouth shows `shape` from `start` until the next cue's start (the last one until the clip
// ends).
struct MouthCue {
    double start = 0.0;
    MouthShape shape = MouthShape::X;
    friend bool operator==(const MouthCue &, const MouthCue &) = default;
};

} // namespace finbook::model::lipsync
