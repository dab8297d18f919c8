// From timed phones to mouth cues, and from cues to one mouth shape per frame (issue 49). The
// rules are the animator's rules that Rhubarb Lip Sync documents and applies (its README and
// its animation steps), rewritten here for frames: times are seconds, `fps` is the document's.
//
// mouthCuesFromPhones applies, in this order:
//  1. Clean-up. Phones with a non-finite or negative time or no length are dropped; a phone
//     that starts before the previous one ends starts when it ends. Phones are upper-cased and
//     lose their stress digits ("AA1" is "AA"). SIL, SP, SPN, NSN and "" are silence; so is
//     every gap between phones and the time from 0 to the first phone.
//  2. The shape of each phone. Vowels: AA D, AE C, EH C, AH C (D when 0.20 s or longer),
//     AO E, ER E (C when under 0.07 s), IH B, IY B, UH F, UW F. Diphthongs show two shapes,
//     the first for 60 % of the phone: AW C→E (D→E from 0.30 s), AY C→B (D→B from 0.20 s),
//     EY C→B, OW E→F, OY E→B. Consonants: M B P A; F V G; L H; W F; T D CH JH TH DH S Z SH ZH
//     B or F; K G B C E F or H; N B C F or H; NG B C E or F; R B E or F; Y B C or F; HH any
//     shape but X (it is shaped by its neighbours); any other symbol B. Where a consonant may take
//     several shapes it takes the shape of the vowel that follows within 0.20 s if allowed (the
//     mouth anticipates vowels), else keeps the previous shape if allowed (no needless movement),
//     else its first shape.
//  3. Closures. The A of M, B and P starts before the sound, by half the previous shape's
//     length clamped to 0.04–0.12 s (never before 0 nor before the previous shape starts),
//     so the lips are closed when the sound is heard. B and P are heard as the lips part: the
//     sound itself may take any shape but X, so rule 2 gives it the vowel that follows.
//  4. Pauses. Silence at the start and the end is X. A silence between speech shorter than
//     0.12 s holds the previous shape; up to 0.35 s it shows the previous shape relaxed
//     (D E→C, C F H→B, G→X; A B keep theirs), relaxed again while that is the next shape
//     (X when it cannot be); longer silences are X.
//  5. Two frames at least. No shape but A lasts less than 2 frames at `fps`. A shape that is
//     too short starts earlier, taking time from the previous shape if that keeps its own two
//     frames (a closure A keeps one: in quick speech the vowel between two closures, as in
//     "Bob", is shorter than two frames, and must still open the mouth); otherwise it is
//     dropped and the previous shape holds through its time (after an A, the next shape
//     starts early instead). A closure A may be shorter than a frame: see
//     mouthShapesPerFrame.
//  6. Tweens for big jumps, as Rhubarb inserts them: D→A, D→G: C at the end of the D; D→B: C
//     across the change; D→X: C at the start of the X; C→F, F→C, D→F: E across the change;
//     H→F: E at the start of the F; F→H: E at the end of the F. A tween lasts a third of the
//     shape it is taken from (a quarter of each across a change), at most
//     max(0.08 s, 2 frames), and is left out when that is less than max(0.04 s, 2 frames).
//  7. The last cue is an X at the end of the last phone (the mouth rests after speaking), or a
//     tween later when rule 6 closes a D through C.
// Not applied: Rhubarb's re-timing of closed/open segments, its choice among shapes by a
// table of efforts, its avoidance of long static segments and its reduced shape sets.
#pragma once

#include <finbook/model/lipsync/mouth_shape.h>

#include <vector>

namespace finbook::model::lipsync {

// The cues for `phones` (any order) by the rules above; a cue at 0 and an X cue last. An empty
// list gives one X at 0. An `fps` that is not a finite number above 0 leaves out rule 5 and
// the two-frame part of rule 6.
std::vector<MouthCue> mouthCuesFromPhones(const std::vector<TimedPhone> &phones, double fps);

// One shape per frame: frame i covers [i/fps, (i+1)/fps) and shows the shape that covers most
// of it (a tie goes to the later shape: the mouth leads the sound), except that a closure A
// anywhere inside the frame wins it, so that a short closure is never lost between frames.
// Time before the first cue is X. `cues` need not be normalized. An `fps` that is not a finite
// number above 0 gives frames of X; a `frameCount` below 1 gives none.
std::vector<MouthShape> mouthShapesPerFrame(const std::vector<MouthCue> &cues, double fps,
                                            int frameCount);

// Cues in time order with no two in a row showing the same shape: non-finite starts dropped,
// a stable sort by start, of cues sharing a start the last one kept.
std::vector<MouthCue> normalizedCues(std::vector<MouthCue> cues);

} // namespace finbook::model::lipsync
