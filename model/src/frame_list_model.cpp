#include "id_mime.h"

#include <finbook/model/commands.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/frame_list_model.h>

#include <QCoreApplication>
#include <QDataStream>
#include <QIODevice>
#include <QMimeData>

#include <algorithm>

namespace finbook::model {

namespace {

const QList<int> kPositionRoles{FrameListModel::FrameNumberRole, FrameListModel::InPlayRangeRole,
                                Qt::ToolTipRole, Qt::AccessibleTextRole};
} // namespace

FrameListModel::FrameListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_doc(document)
{
    rebuild();
    const auto reset = [this] {
        beginResetModel();
        m_revisions.clear();
        rebuild();
        endResetModel();
    };
    connect(m_doc, &Document::documentReset, this, reset);
    // The frames are the current layer's: another layer, other rows.
    connect(m_doc, &Document::currentLayerChanged, this, reset);
    connect(m_doc, &Document::framesInserted, this, &FrameListModel::onFramesInserted);
    connect(m_doc, &Document::framesRemoved, this, &FrameListModel::onFramesRemoved);
    connect(m_doc, &Document::frameMoved, this, &FrameListModel::onFrameMoved);
    connect(m_doc, &Document::frameChanged, this, &FrameListModel::onFrameChanged);
    connect(m_doc, &Document::settingsChanged, this,
            [this] { positionsChanged(0, rowCount() - 1); });
    connect(m_doc, &Document::cameraChanged, this, [this] {
        if (rowCount() > 0)
            emit dataChanged(index(0), index(rowCount() - 1), {CameraKeyRole});
    });
}

void FrameListModel::rebuild()
{
    m_ids.clear();
    for (const Frame &f : m_doc->frames())
        m_ids.push_back(f.id);
}

Id FrameListModel::frameId(int row) const
{
    return row >= 0 && row < int(m_ids.size()) ? m_ids[std::size_t(row)] : kNoId;
}

int FrameListModel::rowOfFrame(Id id) const
{
    const auto it = std::find(m_ids.begin(), m_ids.end(), id);
    return it == m_ids.end() ? -1 : int(it - m_ids.begin());
}

void FrameListModel::onFramesInserted(int first, int count)
{
    beginInsertRows({}, first, first + count - 1);
    for (int i = 0; i < count; ++i)
        m_ids.insert(m_ids.begin() + first + i, m_doc->frameAt(first + i).id);
    endInsertRows();
    positionsChanged(first + count, rowCount() - 1);
}

void FrameListModel::onFramesRemoved(int first, int count)
{
    beginRemoveRows({}, first, first + count - 1);
    for (int i = 0; i < count; ++i)
        m_revisions.remove(m_ids[std::size_t(first + i)]);
    m_ids.erase(m_ids.begin() + first, m_ids.begin() + first + count);
    endRemoveRows();
    positionsChanged(first, rowCount() - 1);
}

void FrameListModel::onFrameMoved(int from, int to)
{
    // Qt counts the destination before the move happens: one past `to` when moving right.
    beginMoveRows({}, from, from, {}, to > from ? to + 1 : to);
    const Id moving = m_ids[std::size_t(from)];
    m_ids.erase(m_ids.begin() + from);
    m_ids.insert(m_ids.begin() + to, moving);
    endMoveRows();
    positionsChanged(std::min(from, to), std::max(from, to));
}

void FrameListModel::onFrameChanged(Id id)
{
    ++m_revisions[id];
    const int row = rowOfFrame(id);
    if (row >= 0)
        emit dataChanged(index(row), index(row));
}

void FrameListModel::positionsChanged(int first, int last)
{
    if (first <= last && first >= 0)
        emit dataChanged(index(first), index(last), kPositionRoles);
}

int FrameListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_ids.size());
}

QVariant FrameListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const int row = index.row();
    const Id id = m_ids[std::size_t(row)];
    const Frame *f = row < m_doc->frameCount() && m_doc->frameAt(row).id == id
                         ? &m_doc->frameAt(row)
                         : m_doc->frame(id);
    if (!f)
        return {};
    switch (role) {
    case FrameIdRole:
        return QVariant::fromValue<quint64>(id);
    case FrameNumberRole:
        return row + 1;
    case HoldRole:
    case Qt::EditRole:
        return f->hold;
    case RevisionRole:
        return QVariant::fromValue<quint64>(revision(id));
    case InPlayRangeRole:
        return row >= m_doc->playFirst() && row <= m_doc->playLast();
    case CameraKeyRole: {
        const std::vector<CameraKey> &keys = m_doc->camera().keys;
        if (keys.empty())
            return false;
        const qint64 start = exposureTicks(m_doc->frames(), 0, row - 1);
        const qint64 end = start + std::clamp(f->hold, 1, kMaxHold);
        const auto first =
            std::lower_bound(keys.begin(), keys.end(), start,
                             [](const CameraKey &k, qint64 tick) { return k.tick < tick; });
        return first != keys.end() && first->tick < end;
    }
    case Qt::ToolTipRole:
    case Qt::AccessibleTextRole:
        return f->hold > 1 ? tr("Frame %1, held for %n frame(s)", nullptr, f->hold).arg(row + 1)
                           : tr("Frame %1").arg(row + 1);
    default:
        return {};
    }
}

bool FrameListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return false;
    if (role != HoldRole && role != Qt::EditRole)
        return false;
    bool ok = false;
    const int hold = value.toInt(&ok);
    if (!ok || hold < 1 || hold > kMaxHold)
        return false;
    const Id id = m_ids[std::size_t(index.row())];
    if (m_doc->frame(id)->hold == hold)
        return true;
    m_doc->undoStack()->push(new SetFrameHoldCommand(m_doc, id, hold));
    return true;
}

Qt::ItemFlags FrameListModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::ItemIsDropEnabled;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled |
           Qt::ItemIsDropEnabled | Qt::ItemIsEditable | Qt::ItemNeverHasChildren;
}

QHash<int, QByteArray> FrameListModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractListModel::roleNames();
    names.insert(FrameIdRole, "frameId");
    names.insert(FrameNumberRole, "frameNumber");
    names.insert(HoldRole, "hold");
    names.insert(RevisionRole, "revision");
    names.insert(InPlayRangeRole, "inPlayRange");
    names.insert(CameraKeyRole, "cameraKey");
    return names;
}

QStringList FrameListModel::mimeTypes() const
{
    return {QString::fromLatin1(kMimeType)};
}

QMimeData *FrameListModel::mimeData(const QModelIndexList &indexes) const
{
    std::vector<Id> ids;
    for (const QModelIndex &i : indexes)
        if (i.isValid())
            ids.push_back(frameId(i.row()));
    return idsToMime(kMimeType, ids);
}

int FrameListModel::dropTarget(int row, const QModelIndex &parent) const
{
    if (parent.isValid())
        return parent.row(); // dropped onto a frame: take its place
    return row < 0 || row > rowCount() ? rowCount() : row;
}

bool FrameListModel::canDropMimeData(const QMimeData *data, Qt::DropAction action, int, int,
                                     const QModelIndex &) const
{
    if (action != Qt::MoveAction || !data || !data->hasFormat(QString::fromLatin1(kMimeType)))
        return false;
    const std::vector<Id> ids = idsFromMime(data, kMimeType);
    return ids.size() == 1 && rowOfFrame(ids.front()) >= 0;
}

bool FrameListModel::dropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                                  const QModelIndex &parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    const int from = rowOfFrame(idsFromMime(data, kMimeType).front());
    int slot = dropTarget(row, parent);
    if (parent.isValid() && slot > from)
        ++slot; // onto a frame to the right: land after it, where it was
    return moveRows({}, from, 1, {}, slot);
}

bool FrameListModel::moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                              const QModelIndex &destinationParent, int destinationChild)
{
    if (sourceParent.isValid() || destinationParent.isValid() || count != 1)
        return false;
    if (sourceRow < 0 || sourceRow >= rowCount() || destinationChild < 0 ||
        destinationChild > rowCount())
        return false;
    const int to = destinationChild > sourceRow ? destinationChild - 1 : destinationChild;
    if (to == sourceRow)
        return false;
    m_doc->undoStack()->push(new MoveFrameCommand(m_doc, sourceRow, to));
    return true;
}

} // namespace finbook::model
