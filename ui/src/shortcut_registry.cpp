#include <finbook/ui/shortcut_registry.h>

#include <QSettings>

#include <algorithm>

namespace finbook::ui {

namespace {
const QString kGroup = QStringLiteral("shortcuts");
QKeySequence keys(const QString &portable)
{
    return QKeySequence(portable, QKeySequence::PortableText);
}
} // namespace

ShortcutRegistry::ShortcutRegistry(QObject *parent)
    : QObject(parent)
{}

const QHash<QString, QKeySequence> &ShortcutRegistry::defaultMap()
{
    // Space is held to pan and never a shortcut; play/pause takes Return. ',' and '.' step
    // frames (Pencil2D, Krita); single letters pick tools (B, E, V, H; P for the pin tool).
    static const QHash<QString, QKeySequence> map{
        {QStringLiteral("file.new"), QKeySequence(QKeySequence::New)},
        {QStringLiteral("file.open"), QKeySequence(QKeySequence::Open)},
        {QStringLiteral("file.save"), QKeySequence(QKeySequence::Save)},
        {QStringLiteral("file.saveAs"), QKeySequence(QKeySequence::SaveAs)},
        {QStringLiteral("file.export"), keys(QStringLiteral("Ctrl+Shift+E"))},
        {QStringLiteral("file.quit"), QKeySequence(QKeySequence::Quit)},
        {QStringLiteral("edit.undo"), QKeySequence(QKeySequence::Undo)},
        {QStringLiteral("edit.redo"), QKeySequence(QKeySequence::Redo)},
        {QStringLiteral("edit.cut"), QKeySequence(QKeySequence::Cut)},
        {QStringLiteral("edit.copy"), QKeySequence(QKeySequence::Copy)},
        {QStringLiteral("edit.paste"), QKeySequence(QKeySequence::Paste)},
        {QStringLiteral("edit.delete"), QKeySequence(QKeySequence::Delete)},
        {QStringLiteral("edit.selectAll"), QKeySequence(QKeySequence::SelectAll)},
        {QStringLiteral("edit.deselect"), keys(QStringLiteral("Ctrl+Shift+A"))},
        {QStringLiteral("edit.preferences"), keys(QStringLiteral("Ctrl+,"))},
        {QStringLiteral("view.zoomIn"), QKeySequence(QKeySequence::ZoomIn)},
        {QStringLiteral("view.zoomOut"), QKeySequence(QKeySequence::ZoomOut)},
        {QStringLiteral("view.fit"), keys(QStringLiteral("Ctrl+0"))},
        {QStringLiteral("view.actualSize"), keys(QStringLiteral("Ctrl+1"))},
        {QStringLiteral("view.onionSkin"), keys(QStringLiteral("O"))},
        {QStringLiteral("view.showMesh"), keys(QStringLiteral("M"))},
        {QStringLiteral("tool.pen"), keys(QStringLiteral("B"))},
        {QStringLiteral("tool.eraser"), keys(QStringLiteral("E"))},
        {QStringLiteral("tool.select"), keys(QStringLiteral("V"))},
        {QStringLiteral("tool.hand"), keys(QStringLiteral("H"))},
        {QStringLiteral("tool.pin"), keys(QStringLiteral("P"))},
        {QStringLiteral("frame.insertAfter"), keys(QStringLiteral("Ins"))},
        {QStringLiteral("frame.insertBefore"), keys(QStringLiteral("Ctrl+F5"))},
        {QStringLiteral("frame.duplicate"), keys(QStringLiteral("Ctrl+D"))},
        {QStringLiteral("frame.delete"), keys(QStringLiteral("Shift+F5"))},
        {QStringLiteral("frame.moveLeft"), keys(QStringLiteral("Alt+Left"))},
        {QStringLiteral("frame.moveRight"), keys(QStringLiteral("Alt+Right"))},
        {QStringLiteral("frame.holdMore"), keys(QStringLiteral("Alt+="))},
        {QStringLiteral("frame.holdLess"), keys(QStringLiteral("Alt+-"))},
        {QStringLiteral("frame.previous"), keys(QStringLiteral(","))},
        {QStringLiteral("frame.next"), keys(QStringLiteral("."))},
        {QStringLiteral("playback.toggle"), keys(QStringLiteral("Return"))},
        {QStringLiteral("playback.loop"), keys(QStringLiteral("Ctrl+L"))},
        {QStringLiteral("object.new"), keys(QStringLiteral("Ctrl+Shift+N"))},
        {QStringLiteral("object.merge"), keys(QStringLiteral("Ctrl+E"))},
        {QStringLiteral("object.raise"), keys(QStringLiteral("Ctrl+]"))},
        {QStringLiteral("object.lower"), keys(QStringLiteral("Ctrl+["))},
        {QStringLiteral("help.shortcuts"), keys(QStringLiteral("Ctrl+/"))},
    };
    return map;
}

void ShortcutRegistry::registerAction(QAction *action)
{
    const QString name = action->objectName();
    if (name.isEmpty() || m_entries.contains(name))
        return;
    const auto preferred = defaultMap().constFind(name);
    Entry entry{action, preferred != defaultMap().constEnd() ? *preferred : action->shortcut()};
    m_entries.insert(name, entry);
    m_order << name;
    action->setShortcut(m_stored.value(name, entry.defaultKeys));
    connect(action, &QObject::destroyed, this, [this, name] {
        m_entries.remove(name);
        m_order.removeAll(name);
    });
    emit shortcutsChanged();
}

QList<QAction *> ShortcutRegistry::actions() const
{
    QList<QAction *> list;
    for (const QString &name : m_order)
        if (QAction *a = m_entries.value(name).action)
            list << a;
    return list;
}

QAction *ShortcutRegistry::action(const QString &name) const
{
    return m_entries.value(name).action;
}

QKeySequence ShortcutRegistry::defaultShortcut(const QString &name) const
{
    return m_entries.value(name).defaultKeys;
}

QKeySequence ShortcutRegistry::shortcut(const QString &name) const
{
    const QAction *a = action(name);
    return a ? a->shortcut() : QKeySequence();
}

QMap<QString, QKeySequence> ShortcutRegistry::currentMap() const
{
    QMap<QString, QKeySequence> map;
    for (const QString &name : m_order)
        map.insert(name, shortcut(name));
    return map;
}

void ShortcutRegistry::apply(const QMap<QString, QKeySequence> &shortcuts)
{
    for (auto it = shortcuts.begin(); it != shortcuts.end(); ++it) {
        if (QAction *a = action(it.key()))
            a->setShortcut(it.value());
        m_stored.insert(it.key(), it.value());
    }
    emit shortcutsChanged();
}

void ShortcutRegistry::resetToDefaults()
{
    m_stored.clear();
    for (const QString &name : m_order)
        if (QAction *a = action(name))
            a->setShortcut(defaultShortcut(name));
    emit shortcutsChanged();
}

std::vector<ShortcutRegistry::Conflict>
ShortcutRegistry::conflicts(const QMap<QString, QKeySequence> &map)
{
    QMap<QString, QStringList> byKeys; // portable text → names, sorted by key for stable output
    for (auto it = map.begin(); it != map.end(); ++it)
        if (!it.value().isEmpty())
            byKeys[it.value().toString(QKeySequence::PortableText)] << it.key();
    std::vector<Conflict> found;
    for (auto it = byKeys.begin(); it != byKeys.end(); ++it) {
        if (it.value().size() < 2)
            continue;
        QStringList names = it.value();
        names.sort();
        found.push_back({keys(it.key()), names});
    }
    return found;
}

void ShortcutRegistry::load(QSettings &settings)
{
    settings.beginGroup(kGroup);
    for (const QString &name : settings.childKeys()) {
        const QKeySequence seq = keys(settings.value(name).toString());
        m_stored.insert(name, seq);
        if (QAction *a = action(name))
            a->setShortcut(seq);
    }
    settings.endGroup();
    emit shortcutsChanged();
}

void ShortcutRegistry::save(QSettings &settings) const
{
    settings.remove(kGroup);
    settings.beginGroup(kGroup);
    for (const QString &name : m_order)
        if (shortcut(name) != defaultShortcut(name))
            settings.setValue(name, shortcut(name).toString(QKeySequence::PortableText));
    // Choices for actions this window has not created (e.g. a tool added later) are kept.
    for (auto it = m_stored.begin(); it != m_stored.end(); ++it)
        if (!m_entries.contains(it.key()))
            settings.setValue(it.key(), it.value().toString(QKeySequence::PortableText));
    settings.endGroup();
}

} // namespace finbook::ui
