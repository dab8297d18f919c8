// The translation context of every .finbook and file-writing message (private to the model).
#pragma once

#include <QCoreApplication>

namespace finbook::model::file_format {

// A class so lupdate files the strings under "FinbookFile".
class FinbookFile {
    Q_DECLARE_TR_FUNCTIONS(FinbookFile)
};

} // namespace finbook::model::file_format
