// The translation context of export messages ("Export"), and a shorthand to build errors.
#pragma once

#include <finbook/model/export/export_options.h>

#include <QCoreApplication>

namespace finbook::model {

struct Export {
    Q_DECLARE_TR_FUNCTIONS(Export)
};

inline ExportError exportError(ExportErrorCode code, const QString &message,
                               const QString &detail = {})
{
    return ExportError{code, message, detail};
}

} // namespace finbook::model
