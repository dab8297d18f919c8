#include <finbook/ui/i18n/action_text.h>

#include <QAction>
#include <QVariant>

namespace finbook::ui {

namespace {

// The dynamic properties remember what this file set, to tell it from an explicit value.
constexpr char kIconTextSet[] = "finbookPlainIconText";
constexpr char kShortcutName[] = "finbookShortcutName";
constexpr char kToolTipSet[] = "finbookPlainToolTip";

// Qt's rule for icon texts and tooltips derived from the text (qt_strippedText in qaction.cpp).
QString qtDerivedText(QString text)
{
    text.remove(QStringLiteral("..."));
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text.at(i) == QLatin1Char('&'))
            text.remove(i, 1);
    }
    return text.trimmed();
}

bool isBracketedMnemonic(const QString &text, qsizetype i)
{
    return i + 3 < text.size() && text.at(i) == QLatin1Char('(') &&
           text.at(i + 1) == QLatin1Char('&') && text.at(i + 2) != QLatin1Char('&') &&
           !text.at(i + 2).isSpace() && text.at(i + 3) == QLatin1Char(')');
}

// Replaces `current` when it is Qt's derived value or the one this file set last time.
template <typename Get, typename Set>
void follow(QAction *action, const char *property, const Get &get, const Set &set)
{
    const QString current = get();
    const QVariant last = action->property(property);
    const bool derived =
        current == qtDerivedText(action->text()) || (last.isValid() && current == last.toString());
    const QString wanted = plainIconText(action->text());
    if (!derived || current == wanted)
        return;
    action->setProperty(property, wanted);
    set(wanted);
}

void sync(QAction *action)
{
    follow(
        action, kIconTextSet, [action] { return action->iconText(); },
        [action](const QString &t) { action->setIconText(t); });
    follow(
        action, kToolTipSet, [action] { return action->toolTip(); },
        [action](const QString &t) { action->setToolTip(t); });
}

} // namespace

QString shortcutName(const QAction *action)
{
    const QVariant name = action->property(kShortcutName);
    return name.isValid() ? name.toString() : withoutMnemonic(action->text());
}

void setShortcutName(QAction *action, const QString &name)
{
    action->setProperty(kShortcutName, name);
}

QString withoutMnemonic(const QString &text)
{
    QString out;
    out.reserve(text.size());
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (isBracketedMnemonic(text, i)) {
            while (!out.isEmpty() && out.back().isSpace())
                out.chop(1);
            i += 3;
        } else if (c == QLatin1Char('&')) {
            if (i + 1 < text.size() && text.at(i + 1) == QLatin1Char('&')) {
                out += c;
                ++i;
            }
        } else {
            out += c;
        }
    }
    return out;
}

QString plainIconText(const QString &text)
{
    return withoutMnemonic(text).remove(QStringLiteral("...")).trimmed();
}

void keepIconTextPlain(QAction *action)
{
    if (!action || action->isSeparator())
        return;
    sync(action);
    QObject::connect(action, &QAction::changed, action, [action] { sync(action); });
}

void keepIconTextsPlain(QObject *root)
{
    if (!root)
        return;
    for (QAction *action : root->findChildren<QAction *>())
        keepIconTextPlain(action);
}

} // namespace finbook::ui
