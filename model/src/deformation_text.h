// The translation context of deformation messages ("Deformation"); a class, so lupdate files
// the strings under it.
#pragma once

#include <QCoreApplication>

namespace finbook::model {

struct Deformation {
    Q_DECLARE_TR_FUNCTIONS(Deformation)
};

} // namespace finbook::model
