// The translation context of every undo command's text ("Command"); a class, so lupdate
// files the strings under it.
#pragma once

#include <QCoreApplication>

namespace finbook::model {

struct Command {
    Q_DECLARE_TR_FUNCTIONS(Command)
};

} // namespace finbook::model
