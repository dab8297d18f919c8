// The "refr" section of a .finbook (layout in finbook_file_format.h): private to the model.
#pragma once

#include <finbook/model/finbook_file.h>

namespace finbook::model::file_format {

// The reference as an ancillary section for serializeFinbook.
AncillarySection referenceSection(const Reference &reference);

} // namespace finbook::model::file_format
