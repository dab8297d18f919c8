#include <finbook/ui/keys/shortcut_registry.h>

#include <QSettings>

#include <algorithm>

namespace finbook::ui {

namespace {
const QString kShortcutsGroup = QStringLiteral("shortcuts");
QKeySequence keys(const QString &portable)
{
    return QKeySequence(portable, QKeySequence::PortableText);
}
} // namespace

ShortcutRegistry::ShortcutRegistry(QObject *parent)
    : QObject(parent)
{}

const QHash<QString, KeyList> &ShortcutRegistry::defaultMap()
{
    // Space is held to pan and never a shortcut; play/pause takes Return. ',' and '.' step
    // frames (Pencil2D, Krita); single letters pick tools (B, E, V, H; P for the pin tool).
    // Second shortcuts are the other habits animators bring: Ctrl+Y redoes (Windows, Krita),
    // Backspace deletes (macOS), Ctrl+= zooms in without Shift.
    const auto standard = [](QKeySequence::StandardKey key) { return KeyList{QKeySequence(key)}; };
    const auto portable = [](std::initializer_list<const char *> texts) {
        KeyList list;
        for (const char *text : texts)
            list << keys(QString::fromLatin1(text));
        return list;
    };
    static const QHash<QString, KeyList> map{
        {QStringLiteral("file.new"), standard(QKeySequence::New)},
        {QStringLiteral("file.open"), standard(QKeySequence::Open)},
        {QStringLiteral("file.save"), standard(QKeySequence::Save)},
        // QKeySequence::SaveAs is empty on X11 without a desktop theme.
        {QStringLiteral("file.saveAs"), portable({"Ctrl+Shift+S"})},
        {QStringLiteral("file.export"), portable({"Ctrl+Shift+E"})},
        {QStringLiteral("file.quit"), standard(QKeySequence::Quit)},
        {QStringLiteral("edit.undo"), portable({"Ctrl+Z"})},
        {QStringLiteral("edit.redo"), portable({"Ctrl+Shift+Z", "Ctrl+Y"})},
        {QStringLiteral("edit.cut"), standard(QKeySequence::Cut)},
        {QStringLiteral("edit.copy"), standard(QKeySequence::Copy)},
        {QStringLiteral("edit.paste"), standard(QKeySequence::Paste)},
        {QStringLiteral("edit.delete"), portable({"Del", "Backspace"})},
        {QStringLiteral("edit.selectAll"), standard(QKeySequence::SelectAll)},
        {QStringLiteral("edit.deselect"), portable({"Ctrl+Shift+A"})},
        {QStringLiteral("edit.preferences"), portable({"Ctrl+,"})},
        {QStringLiteral("view.zoomIn"), portable({"Ctrl++", "Ctrl+="})},
        {QStringLiteral("view.zoomOut"), portable({"Ctrl+-"})},
        {QStringLiteral("view.fit"), portable({"Ctrl+0"})},
        {QStringLiteral("view.actualSize"), portable({"Ctrl+1"})},
        {QStringLiteral("view.onionSkin"), portable({"O"})},
        {QStringLiteral("view.showMesh"), portable({"M"})},
        {QStringLiteral("view.cameraView"), portable({"Shift+V"})},
        // Krita's keys for turning the view; its M (mirror) shows the mesh here.
        {QStringLiteral("view.rotateLeft"), portable({"4"})},
        {QStringLiteral("view.rotateRight"), portable({"6"})},
        {QStringLiteral("view.resetRotation"), portable({"5"})},
        {QStringLiteral("view.mirror"), portable({"Shift+M"})},
        {QStringLiteral("tool.pen"), portable({"B"})},
        {QStringLiteral("tool.eraser"), portable({"E"})},
        {QStringLiteral("tool.select"), portable({"V"})},
        {QStringLiteral("tool.hand"), portable({"H"})},
        {QStringLiteral("tool.pin"), portable({"P"})},
        {QStringLiteral("frame.insertAfter"), portable({"Ins"})},
        {QStringLiteral("frame.insertBefore"), portable({"Ctrl+F5"})},
        {QStringLiteral("frame.duplicate"), portable({"Ctrl+D"})},
        {QStringLiteral("frame.delete"), portable({"Shift+F5"})},
        {QStringLiteral("frame.moveLeft"), portable({"Alt+Left"})},
        {QStringLiteral("frame.moveRight"), portable({"Alt+Right"})},
        {QStringLiteral("frame.holdMore"), portable({"Alt+="})},
        {QStringLiteral("frame.holdLess"), portable({"Alt+-"})},
        {QStringLiteral("frame.previous"), portable({","})},
        {QStringLiteral("frame.next"), portable({"."})},
        {QStringLiteral("playback.toggle"), portable({"Return"})},
        {QStringLiteral("playback.loop"), portable({"Ctrl+L"})},
        {QStringLiteral("object.new"), portable({"Ctrl+Shift+N"})},
        {QStringLiteral("layer.new"), portable({"Ctrl+Alt+N"})},
        {QStringLiteral("layer.moveUp"), portable({"Ctrl+PgUp"})},
        {QStringLiteral("layer.moveDown"), portable({"Ctrl+PgDown"})},
        {QStringLiteral("layer.above"), portable({"PgUp"})},
        {QStringLiteral("layer.below"), portable({"PgDown"})},
        {QStringLiteral("object.merge"), portable({"Ctrl+E"})},
        {QStringLiteral("object.raise"), portable({"Ctrl+]"})},
        {QStringLiteral("object.lower"), portable({"Ctrl+["})},
        {QStringLiteral("deform.apply"), portable({"Ctrl+Shift+P"})},
        {QStringLiteral("help.manual"), portable({"F1"})},
        {QStringLiteral("help.shortcuts"), portable({"Ctrl+/"})},
    };
    return map;
}

KeyList ShortcutRegistry::cleaned(const KeyList &list)
{
    KeyList out;
    for (const QKeySequence &seq : list)
        if (!seq.isEmpty() && !out.contains(seq))
            out << seq;
    return out;
}

void ShortcutRegistry::registerAction(QAction *action)
{
    const QString name = action->objectName();
    if (name.isEmpty() || m_entries.contains(name))
        return;
    const auto preferred = defaultMap().constFind(name);
    Entry entry{action,
                cleaned(preferred != defaultMap().constEnd() ? *preferred : action->shortcuts())};
    m_entries.insert(name, entry);
    m_order << name;
    action->setShortcuts(m_stored.value(name, entry.defaultKeys));
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

KeyList ShortcutRegistry::defaultShortcuts(const QString &name) const
{
    return m_entries.value(name).defaultKeys;
}

KeyList ShortcutRegistry::shortcuts(const QString &name) const
{
    const QAction *a = action(name);
    return a ? a->shortcuts() : KeyList();
}

QKeySequence ShortcutRegistry::defaultShortcut(const QString &name) const
{
    return defaultShortcuts(name).value(0);
}

QKeySequence ShortcutRegistry::shortcut(const QString &name) const
{
    return shortcuts(name).value(0);
}

QMap<QString, KeyList> ShortcutRegistry::currentMap() const
{
    QMap<QString, KeyList> map;
    for (const QString &name : m_order)
        map.insert(name, shortcuts(name));
    return map;
}

void ShortcutRegistry::apply(const QMap<QString, KeyList> &shortcuts)
{
    for (auto it = shortcuts.begin(); it != shortcuts.end(); ++it) {
        const KeyList list = cleaned(it.value());
        if (QAction *a = action(it.key()))
            a->setShortcuts(list);
        m_stored.insert(it.key(), list);
    }
    emit shortcutsChanged();
}

void ShortcutRegistry::apply(const QMap<QString, QKeySequence> &shortcuts)
{
    QMap<QString, KeyList> lists;
    for (auto it = shortcuts.begin(); it != shortcuts.end(); ++it)
        lists.insert(it.key(), KeyList{it.value()});
    apply(lists);
}

void ShortcutRegistry::resetToDefaults()
{
    m_stored.clear();
    for (const QString &name : m_order)
        if (QAction *a = action(name))
            a->setShortcuts(defaultShortcuts(name));
    emit shortcutsChanged();
}

std::vector<ShortcutRegistry::Conflict>
ShortcutRegistry::conflicts(const QMap<QString, KeyList> &map)
{
    QMap<QString, QStringList> byKeys; // portable text → names, sorted by key for stable output
    for (auto it = map.begin(); it != map.end(); ++it)
        for (const QKeySequence &seq : cleaned(it.value()))
            byKeys[seq.toString(QKeySequence::PortableText)] << it.key();
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

namespace {
QStringList toStrings(const KeyList &list)
{
    QStringList texts;
    for (const QKeySequence &seq : list)
        texts << seq.toString(QKeySequence::PortableText);
    return texts;
}
} // namespace

void ShortcutRegistry::load(QSettings &settings)
{
    settings.beginGroup(kShortcutsGroup);
    for (const QString &name : settings.childKeys()) {
        // A list since several shortcuts per action; older settings hold one string, which
        // reads as a list of one.
        KeyList list;
        for (const QString &text : settings.value(name).toStringList())
            list << keys(text);
        list = cleaned(list);
        m_stored.insert(name, list);
        if (QAction *a = action(name))
            a->setShortcuts(list);
    }
    settings.endGroup();
    emit shortcutsChanged();
}

void ShortcutRegistry::save(QSettings &settings) const
{
    settings.remove(kShortcutsGroup);
    settings.beginGroup(kShortcutsGroup);
    for (const QString &name : m_order)
        if (shortcuts(name) != defaultShortcuts(name))
            settings.setValue(name, toStrings(shortcuts(name)));
    // Choices for actions this window has not created (e.g. a tool added later) are kept.
    for (auto it = m_stored.begin(); it != m_stored.end(); ++it)
        if (!m_entries.contains(it.key()))
            settings.setValue(it.key(), toStrings(it.value()));
    settings.endGroup();
}

} // namespace finbook::ui
