// Reading the files a user picks in File → Import Reference…, shared by the single picture or
// video (reference_import.cpp) and the picture sequence (reference_sequence.cpp).
#pragma once

#include <finbook/geometry/expected.h>

#include <QByteArray>
#include <QString>

namespace finbook::model::reference_detail {

// "“NAME” cannot be used as a reference: WHY", NAME being the file name of `path`.
QString referenceRefusal(const QString &path, const QString &why);

// The bytes of the regular file at `path`, at most `limit` bytes and not empty; otherwise the
// refusal saying why (`tooLarge` when the file is larger than `limit`).
Expected<QByteArray, QString> readReferenceFile(const QString &path, qint64 limit,
                                                const QString &tooLarge);

} // namespace finbook::model::reference_detail
