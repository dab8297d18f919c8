// Mouth timings made elsewhere, read as cues (seconds from the start of the clip): Papagayo
// projects (.pgo), Moho switch data (.dat, as Papagayo and Rhubarb export it) and Rhubarb Lip
// Sync's results (.tsv, .json, .xml). A damaged or hostile file gives one translatable sentence
// that says what is wrong and where, and no cues; sizes and counts are bounded before anything
// is allocated for them.
#pragma once

#include <finbook/model/lipsync/mouth_shape.h>

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

namespace finbook::model::lipsync {

// Far more than any dialogue needs (an hour of fast speech is some 40,000 cues), few enough
// that a crafted file costs little.
constexpr qint64 kMaxLipSyncFileBytes = 16 * 1024 * 1024;
constexpr int kMaxMouthCues = 1'000'000;
constexpr double kMaxCueSeconds = 24.0 * 60.0 * 60.0;
constexpr double kMaxLipSyncFps = 1000.0;

enum class LipSyncFormat { Papagayo, MohoSwitch, RhubarbTsv, RhubarbJson, RhubarbXml };

// Either cues (normalizedCues: sorted, no repeats; never empty) or an error (cues empty).
struct MouthCueImport {
    std::vector<MouthCue> cues;
    QString error;
    bool ok() const { return error.isEmpty(); }
};

// Papagayo's "lipsync version 1" project: sound path, fps, length in frames, voices → phrases
// → words ("text start end count") → phonemes ("frame name"), frames from 0 at the file's own
// fps. The first voice is read (the others are checked, not used). A phoneme holds until the
// next one of its word, the word's last one through the word's end frame; the mouth rests
// between words. Names are Papagayo's Preston Blair set, mapped as Rhubarb maps them (its
// --datUsePrestonBlair table): MBP A, etc B, E C, AI D, O E, U F, FV G, L H, rest X, and WQ
// (the puckered W of "way", "quick") F. Case is ignored.
MouthCueImport parsePapagayo(const QByteArray &bytes);

// "MohoSwitch1", then "frame name" lines, frames from 1 at `fps` (the document's: the file does
// not say). Names are the Preston Blair set above, or Rhubarb's letters A–H and X (its default
// .dat names) when every name in the file is one of those nine letters ("E" is Preston Blair's
// C unless the file uses letters only).
MouthCueImport parseMohoSwitch(const QByteArray &bytes, double fps);

// Rhubarb's TSV: "seconds<TAB>letter" per line (any blanks between), times never decreasing.
MouthCueImport parseRhubarbTsv(const QByteArray &bytes);

// Rhubarb's JSON: {"metadata": ..., "mouthCues": [{"start": s, "end": s, "value": "X"}, ...]}.
// "end" is checked (not before "start") but not needed: a cue lasts until the next one.
MouthCueImport parseRhubarbJson(const QByteArray &bytes);

// Rhubarb's XML: <rhubarbResult><mouthCues><mouthCue start="s" end="s">X</mouthCue>...
MouthCueImport parseRhubarbXml(const QByteArray &bytes);

// All nine shape letters are accepted in Rhubarb's formats, upper or lower case (Rhubarb may be
// told to use fewer shapes, never others). `fps` is used by MohoSwitch only.
MouthCueImport parseMouthCues(const QByteArray &bytes, LipSyncFormat format, double fps);

// The format by the file's first bytes (a UTF-8 byte order mark and blanks skipped), if it is
// one of the five.
std::optional<LipSyncFormat> sniffLipSyncFormat(const QByteArray &bytes);

// The file at `path`, its format chosen by its suffix (.pgo .dat .tsv .json .xml, any case) or,
// for any other suffix (Rhubarb's own example writes output.txt), by its contents. `fps` is the
// document's, for Moho switch data.
MouthCueImport importMouthCues(const QString &path, double fps);

// For an Open dialog: "Lip sync timings (*.pgo *.dat *.tsv *.txt *.json *.xml)".
QString lipSyncFileFilter();

} // namespace finbook::model::lipsync
