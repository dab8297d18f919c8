// Reading the first frame of a .finbook without reading the rest of it, for thumbnails.
//
// The file's tables (stroke data, poses) list entries in the order frames first use them, so
// the first frame's entries are the first ones of each table. readFirstFrame reads the header,
// the document settings, the first frame's record and the table entries it uses (and the
// section headers on the way, skipping everything else with a seek), then hands exactly those
// bytes, laid out as a one-frame .finbook, to the model's reader: every check that opening
// makes (bounds, counts, finite numbers, ids, rigs, the memory budget set by the size) is made
// on what was read. A section no larger than `wholeSectionBytes` is read whole so that its
// checksum is checked too; a larger one is read only as far as the first frame needs, so a
// 10M-point animation costs what its first frame costs.
#pragma once

#include <finbook/model/finbook_file.h>

namespace finbook::app {

// Sections up to this size are read whole and their checksums checked.
constexpr qint64 kWholeSectionBytes = qint64(4) << 20;
// Files up to this size are first checked whole, as `finbook info` and opening check them
// (every frame, id, sound clip and reference), without keeping what they hold: a thumbnail is
// made of exactly the files that open. Larger ones are checked in the parts read.
constexpr qint64 kWholeCheckBytes = qint64(64) << 20;

// The document holding only the first frame of the file at `path` (its settings as saved).
// Fails, without reading further, on anything opening the file would refuse in the parts it
// read: not a regular file, not a .finbook, a newer format, a damaged or cut-off section, a
// checksum that does not match (sections read whole), values out of range; and, for a file
// of at most `wholeCheckBytes`, on anything opening would refuse anywhere in it.
Expected<model::LoadedDocument, model::FileError>
readFirstFrame(const QString &path, qint64 wholeSectionBytes = kWholeSectionBytes,
               qint64 *bytesRead = nullptr, qint64 wholeCheckBytes = kWholeCheckBytes);

} // namespace finbook::app
