// Upgrading documents read from older .finbook versions.
//
// The reader parses each version's byte layout (it knows the file's version while parsing);
// what changed in meaning is fixed here, one version step at a time, so a version-1 file
// read by Finbook with format 4 runs the steps 1→2, 2→3 and 3→4 in order.
#include "finbook_file_format.h"

#include <array>

namespace finbook::model::file_format {

namespace {
using MigrationStep = void (*)(LoadedDocument &);

// kSteps[i] upgrades a document from version kOldestVersion + i to the next one.
constexpr std::array<MigrationStep, kFinbookFormatVersion - kOldestVersion> kSteps{
    // 1 → 2 added a checksum after each section (the reader's business); what a document
    // holds did not change.
    [](LoadedDocument &) {},
    // 2 → 3 added fills and the close-gap setting: an older file has no fills and closes gaps
    // automatically, which are the defaults.
    [](LoadedDocument &document) { document.settings.closeGap = DocumentSettings().closeGap; },
    // 3 → 4 added layers: an older file is one layer holding all its frames, which is what a
    // document without a layer list becomes (takeLoadedLayers).
    [](LoadedDocument &document) { document.layers.clear(); },
};
} // namespace

void migrateLoadedDocument(LoadedDocument &document, quint32 fromVersion)
{
    for (quint32 v = std::max(fromVersion, kOldestVersion); v < kFinbookFormatVersion; ++v)
        kSteps[v - kOldestVersion](document);
}

} // namespace finbook::model::file_format
