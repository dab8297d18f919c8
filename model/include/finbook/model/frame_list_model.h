// FrameListModel: the document's frames as a flat list, one row per frame, for the timeline.
//
// The model mirrors the frame ids and follows the Document's signals with the matching
// begin/end insert, remove and move calls, so views keep their scroll position and
// persistent indexes across edits and undo. Everything that edits goes through the undo
// stack: dropping frames pushes MoveFrameCommand, editing HoldRole pushes
// SetFrameHoldCommand.
//
// Qt::DisplayRole is left empty on purpose: a frame's number is positional and changes when a
// frame is inserted before it, while row data must travel with its row (the contract
// QAbstractItemModelTester checks). The number lives in FrameNumberRole, refreshed by
// dataChanged after every structural change.
#pragma once

#include <finbook/model/document.h>

#include <QAbstractListModel>
#include <QHash>

#include <vector>

namespace finbook::model {

class FrameListModel : public QAbstractListModel {
    Q_OBJECT
public:
    enum Role {
        FrameIdRole = Qt::UserRole + 1, // Id (quint64)
        FrameNumberRole,                // int, 1-based position
        HoldRole,                       // int, exposure in ticks; editable
        RevisionRole,                   // quint64, bumped whenever the frame's drawing changes
        InPlayRangeRole,                // bool
        CameraKeyRole,                  // bool: a camera key lies in the frame's ticks
    };
    Q_ENUM(Role)

    static constexpr const char *kMimeType = "application/x-finbook-frame-ids";

    explicit FrameListModel(Document *document, QObject *parent = nullptr);

    Document *document() const { return m_doc; }
    Id frameId(int row) const;
    int rowOfFrame(Id frameId) const; // -1 if none
    quint64 revision(Id frameId) const { return m_revisions.value(frameId, 0); }

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
    // Moves the dragged frame so it lands before `row` (or at the end for -1, or before
    // `parent` when dropped onto an item). One MoveFrameCommand per drop.
    bool dropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                      const QModelIndex &parent) override;
    // The same as a drop: one undoable MoveFrameCommand; only count == 1 is supported.
    bool moveRows(const QModelIndex &sourceParent, int sourceRow, int count,
                  const QModelIndex &destinationParent, int destinationChild) override;

private:
    void rebuild();
    void onFramesInserted(int first, int count);
    void onFramesRemoved(int first, int count);
    void onFrameMoved(int from, int to);
    void onFrameChanged(Id frameId);
    void positionsChanged(int first, int last);
    int dropTarget(int row, const QModelIndex &parent) const;

    Document *m_doc;
    std::vector<Id> m_ids;          // mirror of the document's frame order
    QHash<Id, quint64> m_revisions; // per-frame drawing revision
};

} // namespace finbook::model
