// Drag-and-drop payloads of the item models: a list of entity ids under one MIME type.
#pragma once

#include <finbook/model/types.h>

#include <QMimeData>

#include <vector>

namespace finbook::model {

QMimeData *idsToMime(const char *mimeType, const std::vector<Id> &ids);
// The ids stored under `mimeType`, in order; empty for null data or another type.
std::vector<Id> idsFromMime(const QMimeData *data, const char *mimeType);

} // namespace finbook::model
