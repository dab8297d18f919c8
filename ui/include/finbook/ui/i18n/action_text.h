// Action texts as people read them outside a menu (shortcut lists, toolbar buttons, tooltips):
// without the mnemonic marker, in either of its two translated forms.
#pragma once

#include <QString>

class QAction;
class QObject;

namespace finbook::ui {

// `text` without its mnemonic. Handles the Western form ("&Open..." -> "Open...") and the form
// Japanese and Chinese translations use, where the letter follows the text in brackets
// ("開く(&O)..." -> "開く..."). "&&" stays a literal '&'. Everything else is kept.
QString withoutMnemonic(const QString &text);

// An action's name in the shortcut lists (Help → Keyboard Shortcuts, Preferences): the name
// set with setShortcutName() when its text changes as it is used (Undo reads "Undo Change
// Frame Exposure"), else its text, withoutMnemonic().
QString shortcutName(const QAction *action);
void setShortcutName(QAction *action, const QString &name);

// The icon text Qt would derive from `text` if it knew the bracketed form: withoutMnemonic()
// minus "...", trimmed (Qt's own rule for derived icon texts).
QString plainIconText(const QString &text);

// Qt derives an action's icon text and tooltip (what toolbar buttons show) from its text by
// dropping '&' only, so "保存(&S)" shows as "保存(S)". This keeps both derived values plain,
// also after later text changes (Undo's text, Play/Pause). An icon text or tooltip someone set
// explicitly is left alone.
void keepIconTextPlain(QAction *action);

// keepIconTextPlain() for every QAction among `root`'s descendants.
void keepIconTextsPlain(QObject *root);

} // namespace finbook::ui
