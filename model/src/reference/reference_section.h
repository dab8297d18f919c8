// The "refr" section of a .finbook (layout in finbook_file_format.h): private to the model.
#pragma once

#include <finbook/model/finbook_file.h>

namespace finbook::model::file_format {

// The reference as ancillary sections for serializeFinbook: refr, and for a sequence rseq.
std::vector<AncillarySection> referenceSections(const Reference &reference);

} // namespace finbook::model::file_format
