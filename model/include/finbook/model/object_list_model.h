// ObjectListModel: the objects (stroke groups) of one frame, top object first like a layers
// panel. Row r shows group index (count - 1 - r).
//
// It mirrors the frame's object ids and follows Document::groupsChanged with the matching
// insert/remove/move rows where an edit is one of those, so selections survive undo. Edits go
// through the undo stack: the name (EditRole) → RenameObjectCommand, VisibleRole /
// LockedRole / CheckStateRole (visible) → SetObjectFlagCommand, drops and moveRows →
// ReorderObjectCommand.
#pragma once

#include <finbook/model/document.h>

#include <QAbstractListModel>

#include <vector>

namespace finbook::model {

class ObjectListModel : public QAbstractListModel {
    Q_OBJECT
public:
    enum Role {
        GroupIdRole = Qt::UserRole + 1, // Id (quint64)
        VisibleRole,                    // bool, editable
        LockedRole,                     // bool, editable
        StrokeCountRole,                // int: the strokes drawn (lines of no ink left out)
        PosedRole,                      // bool: has pins and a solved pose
    };
    Q_ENUM(Role)

    static constexpr const char *kMimeType = "application/x-finbook-object-ids";

    explicit ObjectListModel(Document *document, QObject *parent = nullptr);

    Document *document() const { return m_doc; }
    // Shows the objects of this frame (kNoId: none).
    void setFrameId(Id frameId);
    Id frameId() const { return m_frameId; }
    Id groupId(int row) const;
    int rowOfGroup(Id groupId) const; // -1 if none
    // Group index (0 = back) for a row, and back.
    int zIndexOfRow(int row) const { return rowCount() - 1 - row; }

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QHash<int, QByteArray> roleNames() const override;

    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QModelIndexList &indexes) const override;
    bool canDropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                         const QModelIndex &parent) const override;
    bool dropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                      const QModelIndex &parent) override;
    // One undoable ReorderObjectCommand; only count == 1 is supported.
    bool moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                  const QModelIndex &destinationParent, int destinationChild) override;

private:
    std::vector<Id> currentIds() const; // top first
    const StrokeGroup *groupAt(int row) const;
    void sync();
    bool syncSingleEdit(const std::vector<Id> &now);

    Document *m_doc;
    Id m_frameId = kNoId;
    std::vector<Id> m_ids; // top first
};

} // namespace finbook::model
