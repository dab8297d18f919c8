// The Fill tool's edits, each one undo step that restores the object's fills exactly: fill a
// region (or recolour the fill it shows), remove a fill, fill every enclosed region of an
// object, and the document's "close gaps" setting.
#pragma once

#include <finbook/model/commands.h>

#include <memory>

namespace finbook::model {

// Replaces an object's fills. Obsolete when the object is gone or nothing would change.
class SetFillsCommand : public DocumentCommand {
public:
    SetFillsCommand(Document *doc, Id groupId, std::vector<Fill> fills, const QString &text,
                    QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    std::vector<Fill> m_new;
    std::vector<Fill> m_old;
};

// The command a Fill-tool click at canvas point `at` (as the object shows now, posed or not)
// makes on object `groupId`: fill the region there with `color`, or recolour the fill it shows.
// Null when there is no region there or nothing would change.
std::unique_ptr<QUndoCommand> fillRegionCommand(Document *doc, Id groupId, QPointF at, QRgb color);
// Removes the fill the region at `at` shows. Null when it shows none.
std::unique_ptr<QUndoCommand> removeFillCommand(Document *doc, Id groupId, QPointF at);
// Fills every enclosed region of the object that shows no fill. Null when there is none.
std::unique_ptr<QUndoCommand> fillAllRegionsCommand(Document *doc, Id groupId, QRgb color);
// Sets the document's close-gap distance (px; < 0 = automatic), touching no other setting.
// Commands with the same `editSerial` merge into one undo step (one session of the Close gaps
// box: every arrow click of it); a session that ends where it began leaves no step. A
// negative serial never merges.
class SetCloseGapCommand : public DocumentCommand {
public:
    SetCloseGapCommand(Document *doc, double closeGap, int editSerial = -1,
                       QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::SetCloseGap); }
    bool mergeWith(const QUndoCommand *other) override;
    void redo() override;
    void undo() override;

private:
    void apply(double closeGap);

    int m_serial;
    double m_new;
    double m_old;
};

// One SetCloseGapCommand. Null when unchanged.
std::unique_ptr<QUndoCommand> setCloseGapCommand(Document *doc, double closeGap,
                                                 int editSerial = -1);

} // namespace finbook::model
