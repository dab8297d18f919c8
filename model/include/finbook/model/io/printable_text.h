// Text from a file, safe to print: a name read from a .finbook may hold terminal escapes.
#pragma once

#include <QString>

namespace finbook::model {

// `text` with every character that could change how a terminal or a one-line message shows
// the rest written out instead: C0 and C1 controls and DEL as \xHH, line and paragraph
// separators and bidirectional embeddings, overrides and isolates as \u{HHHH}. A backslash
// followed by 'x' or 'u' becomes "\\" so escapes stay unambiguous. Anything else, including
// every letter of every script, is kept.
QString printableText(const QString &text);

} // namespace finbook::model
