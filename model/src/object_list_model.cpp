#include "id_mime.h"

#include <finbook/model/commands.h>
#include <finbook/model/object_list_model.h>

#include <QCoreApplication>
#include <QDataStream>
#include <QIODevice>
#include <QMimeData>

#include <algorithm>

namespace finbook::model {

namespace {
bool equalSkipping(const std::vector<Id> &longer, const std::vector<Id> &shorter, std::size_t skip)
{
    for (std::size_t i = 0, j = 0; i < longer.size(); ++i) {
        if (i == skip)
            continue;
        if (longer[i] != shorter[j++])
            return false;
    }
    return true;
}

std::size_t firstMismatch(const std::vector<Id> &a, const std::vector<Id> &b)
{
    std::size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i])
        ++i;
    return i;
}
} // namespace

ObjectListModel::ObjectListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_doc(document)
{
    connect(m_doc, &Document::groupsChanged, this, [this](Id frameId) {
        if (frameId == m_frameId)
            sync();
    });
    connect(m_doc, &Document::frameChanged, this, [this](Id frameId) {
        if (frameId == m_frameId)
            sync();
    });
    connect(m_doc, &Document::framesRemoved, this, &ObjectListModel::sync);
    connect(m_doc, &Document::framesInserted, this, &ObjectListModel::sync);
    connect(m_doc, &Document::documentReset, this, &ObjectListModel::sync);
}

void ObjectListModel::setFrameId(Id frameId)
{
    if (frameId == m_frameId)
        return;
    beginResetModel();
    m_frameId = frameId;
    m_ids = currentIds();
    endResetModel();
}

std::vector<Id> ObjectListModel::currentIds() const
{
    std::vector<Id> ids;
    if (const Frame *f = m_doc->frame(m_frameId))
        for (auto it = f->groups.rbegin(); it != f->groups.rend(); ++it)
            ids.push_back(it->id);
    return ids;
}

Id ObjectListModel::groupId(int row) const
{
    return row >= 0 && row < int(m_ids.size()) ? m_ids[std::size_t(row)] : kNoId;
}

int ObjectListModel::rowOfGroup(Id id) const
{
    const auto it = std::find(m_ids.begin(), m_ids.end(), id);
    return it == m_ids.end() ? -1 : int(it - m_ids.begin());
}

const StrokeGroup *ObjectListModel::groupAt(int row) const
{
    const Id id = groupId(row);
    return id == kNoId ? nullptr : m_doc->group(id);
}

void ObjectListModel::sync()
{
    std::vector<Id> now = currentIds();
    if (now == m_ids) {
        if (!m_ids.empty())
            emit dataChanged(index(0), index(rowCount() - 1));
        return;
    }
    if (syncSingleEdit(now))
        return;
    beginResetModel();
    m_ids = std::move(now);
    endResetModel();
}

// Recognises one inserted, removed or moved object, the edits commands make one at a time.
bool ObjectListModel::syncSingleEdit(const std::vector<Id> &now)
{
    const std::size_t i = firstMismatch(m_ids, now);
    if (now.size() == m_ids.size() + 1 && equalSkipping(now, m_ids, i)) {
        beginInsertRows({}, int(i), int(i));
        m_ids = now;
        endInsertRows();
        return true;
    }
    if (now.size() + 1 == m_ids.size() && equalSkipping(m_ids, now, i)) {
        beginRemoveRows({}, int(i), int(i));
        m_ids = now;
        endRemoveRows();
        return true;
    }
    if (now.size() != m_ids.size() || i >= now.size())
        return false;
    std::size_t j = now.size() - 1;
    while (j > i && m_ids[j] == now[j])
        --j;
    const bool downward =
        now[j] == m_ids[i] &&
        std::equal(now.begin() + long(i), now.begin() + long(j), m_ids.begin() + long(i) + 1);
    const bool upward =
        now[i] == m_ids[j] &&
        std::equal(m_ids.begin() + long(i), m_ids.begin() + long(j), now.begin() + long(i) + 1);
    if (downward)
        beginMoveRows({}, int(i), int(i), {}, int(j) + 1);
    else if (upward)
        beginMoveRows({}, int(j), int(j), {}, int(i));
    else
        return false;
    m_ids = now;
    endMoveRows();
    emit dataChanged(index(0), index(rowCount() - 1));
    return true;
}

int ObjectListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_ids.size());
}

namespace {
// The strokes an animator drew and sees: lines of no ink (gap and cut closers, seams, the parts
// of lines a cut-out piece hid, which Apply Pose keeps) are left out of the count.
int drawnStrokes(const StrokeGroup &g)
{
    return int(std::count_if(g.strokes.begin(), g.strokes.end(),
                             [](const Stroke &s) { return s.data && qAlpha(s.data->color) != 0; }));
}
} // namespace

QVariant ObjectListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const StrokeGroup *g = groupAt(index.row());
    if (!g)
        return {};
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return g->name;
    case Qt::ToolTipRole:
        return QCoreApplication::translate("ObjectListModel", "%1: %n stroke(s)", nullptr,
                                           drawnStrokes(*g))
            .arg(g->name);
    case Qt::CheckStateRole:
        return g->visible ? Qt::Checked : Qt::Unchecked;
    case GroupIdRole:
        return QVariant::fromValue<quint64>(g->id);
    case VisibleRole:
        return g->visible;
    case LockedRole:
        return g->locked;
    case StrokeCountRole:
        return drawnStrokes(*g);
    case PosedRole:
        return g->isDeformed();
    default:
        return {};
    }
}

bool ObjectListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return false;
    const StrokeGroup *g = groupAt(index.row());
    if (!g)
        return false;
    QUndoStack *stack = m_doc->undoStack();
    switch (role) {
    case Qt::EditRole: {
        const QString name = value.toString().trimmed();
        if (name.isEmpty())
            return false;
        if (name != g->name)
            stack->push(new RenameObjectCommand(m_doc, g->id, name));
        return true;
    }
    case Qt::CheckStateRole:
    case VisibleRole: {
        const bool visible =
            role == VisibleRole ? value.toBool() : value.value<Qt::CheckState>() == Qt::Checked;
        if (visible != g->visible)
            stack->push(new SetObjectFlagCommand(m_doc, g->id, ObjectFlag::Visible, visible));
        return true;
    }
    case LockedRole:
        if (value.toBool() != g->locked)
            stack->push(new SetObjectFlagCommand(m_doc, g->id, ObjectFlag::Locked, value.toBool()));
        return true;
    default:
        return false;
    }
}

Qt::ItemFlags ObjectListModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::ItemIsDropEnabled;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsUserCheckable |
           Qt::ItemIsDragEnabled | Qt::ItemNeverHasChildren;
}

QHash<int, QByteArray> ObjectListModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractListModel::roleNames();
    names.insert(GroupIdRole, "groupId");
    names.insert(VisibleRole, "visible");
    names.insert(LockedRole, "locked");
    names.insert(StrokeCountRole, "strokeCount");
    names.insert(PosedRole, "posed");
    return names;
}

QStringList ObjectListModel::mimeTypes() const
{
    return {QString::fromLatin1(kMimeType)};
}

QMimeData *ObjectListModel::mimeData(const QModelIndexList &indexes) const
{
    std::vector<Id> ids;
    for (const QModelIndex &i : indexes)
        if (i.isValid())
            ids.push_back(groupId(i.row()));
    return idsToMime(kMimeType, ids);
}

bool ObjectListModel::canDropMimeData(const QMimeData *data, Qt::DropAction action, int, int,
                                      const QModelIndex &) const
{
    if (action != Qt::MoveAction || !data || !data->hasFormat(QString::fromLatin1(kMimeType)))
        return false;
    const std::vector<Id> ids = idsFromMime(data, kMimeType);
    return ids.size() == 1 && rowOfGroup(ids.front()) >= 0;
}

bool ObjectListModel::dropMimeData(const QMimeData *data, Qt::DropAction action, int row,
                                   int column, const QModelIndex &parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    const int from = rowOfGroup(idsFromMime(data, kMimeType).front());
    int slot = parent.isValid() ? parent.row() : (row < 0 ? rowCount() : row);
    if (parent.isValid() && slot > from)
        ++slot; // onto an object below: take its place
    return moveRows({}, from, 1, {}, slot);
}

bool ObjectListModel::moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                               const QModelIndex &destinationParent, int destinationChild)
{
    if (sourceParent.isValid() || destinationParent.isValid() || count != 1)
        return false;
    if (sourceRow < 0 || sourceRow >= rowCount() || destinationChild < 0 ||
        destinationChild > rowCount())
        return false;
    const int finalRow = destinationChild > sourceRow ? destinationChild - 1 : destinationChild;
    if (finalRow == sourceRow)
        return false;
    m_doc->undoStack()->push(
        new ReorderObjectCommand(m_doc, groupId(sourceRow), zIndexOfRow(finalRow)));
    return true;
}

} // namespace finbook::model
