// Edits on strokes shared by tools and menu actions: adding strokes to the current object
// (creating one if the frame has none), deleting, selecting all, and the clipboard.
// Every edit is one undo step (a macro when it takes several commands).
#pragma once

#include <finbook/model/types.h>

#include <QCoreApplication>
#include <QMimeData>
#include <QPointF>

#include <memory>
#include <optional>
#include <vector>

namespace finbook::ui {

class EditorState;

// MIME type of strokes on the clipboard: a versioned QDataStream of points, colour, width,
// then (version 2) the fills that travel with them.
inline constexpr char kStrokesMimeType[] = "application/x-finbook-strokes";

// A fill copied with the strokes around its region: its colour and a point inside the region
// (rest canvas pixels, as the strokes are copied). Pasted, it fills the region there again.
struct ClipboardFill {
    QRgb color = 0xff000000;
    QPointF seed;
    friend bool operator==(const ClipboardFill &, const ClipboardFill &) = default;
};

struct ClipboardContent {
    std::vector<model::StrokeDataPtr> strokes;
    std::vector<ClipboardFill> fills;
};

QByteArray encodeStrokes(const std::vector<model::StrokeDataPtr> &strokes,
                         const std::vector<ClipboardFill> &fills = {});
// Refuses (nullopt) anything malformed: wrong magic, absurd counts, non-finite values.
// Reads version 1 (strokes only) too.
std::optional<ClipboardContent> decodeStrokes(const QByteArray &bytes);

class StrokeEditing {
    Q_DECLARE_TR_FUNCTIONS(StrokeEditing)
public:
    // Why new strokes cannot go into the current frame now (no frame, locked or hidden
    // object), as a sentence for the status bar; empty when they can.
    static QString targetProblem(const EditorState &state);

    // Adds strokes on top of the current object as one undo step named `text`, creating an
    // object when the frame has none. Returns the new stroke ids, or nullopt with `problem`
    // set when refused.
    static std::optional<std::vector<model::Id>>
    addStrokes(EditorState &state, const std::vector<model::StrokeDataPtr> &strokes,
               const QString &text, QString *problem = nullptr);

    // Removes the selected strokes (one undo step). False when nothing was selected.
    static bool deleteSelection(EditorState &state);
    // Makes the pose of every posed object among `groupIds` its drawing (one Apply Pose
    // command each; the rig stays, rebased onto the new drawing), so an edit that works on
    // rest strokes acts on what is on screen. Returns whether any pose was applied. Call
    // inside the edit's macro.
    static bool applyPoses(model::Document *doc, const std::vector<model::Id> &groupIds);
    // Opens the undo macro of a rest edit on `groupIds` and applies their poses first; the
    // macro's text says "(pose applied)" when it did. Close it with endRestEdit() (or
    // endMacro() when the edit leaves the drawing's outline as it is).
    static void beginRestEdit(model::Document *doc, const QString &text,
                              const std::vector<model::Id> &groupIds);
    // beginRestEdit() for an edit of the strokes `ids` (their objects' poses applied first);
    // returns the strokes the edit acts on. A cut-out pose bakes a line into the parts its
    // pieces showed and the parts a piece hid, the first part keeping the line's id: each
    // stroke comes back with its parts (the new strokes that continue it end to end).
    static std::vector<model::Id> beginRestEditOf(model::Document *doc, const QString &text,
                                                  const std::vector<model::Id> &ids);
    // The objects `groupIds` as they are now (inside a rest edit, after their poses were
    // applied), for showUncoveredLines() once the edit is made.
    static std::vector<model::StrokeGroup> objectsNow(const model::Document *doc,
                                                      const std::vector<model::Id> &groupIds);
    // Inks again the hidden parts of lines (Apply Pose's, under a cut-out piece) that the edit
    // took the cover off since `before` (objectsNow's): a head moved off an arm raised behind
    // it shows the arm's top, and the arm keeps its fill (model/fill/uncovered_lines.h). Call
    // inside the edit's macro.
    static void showUncoveredLines(model::Document *doc,
                                   const std::vector<model::StrokeGroup> &before);
    // Closes a rest edit's macro after letting the skeletons of `following` (from
    // skeletonsFollowing() before the edit, skeleton/skeleton_follow.h) follow the new
    // drawing, so the stroke edit and the skeleton are one undo step.
    static void endRestEdit(EditorState &state, const std::vector<model::Id> &following);
    // Selects every stroke of the visible, unlocked objects of the current frame.
    static void selectAll(EditorState &state);

    static std::vector<model::StrokeDataPtr> selectedData(const EditorState &state);
    // The fills of the current frame whose region is bounded by selected strokes only: the
    // ones a copy of the selection carries.
    static std::vector<ClipboardFill> selectedFills(const EditorState &state);
    // The picked strokes in Finbook's own format and the picked pictures as one picture (as
    // they show), which other programs and Paste take.
    static bool copySelection(const EditorState &state);
    static bool cutSelection(EditorState &state);
    // Pastes clipboard strokes (and the fills copied with them, in the regions they make
    // again) into the current object and selects them. They land centred
    // on `at` (canvas pixels, the mouse over the canvas) when given; else where they were
    // copied if the original is not in this frame (another frame: the drawing stays in
    // register), or offset down and right from it, one more step for each copy already
    // there, so a paste never hides under its original. Returns false (with `problem` set if
    // refused) when nothing was pasted.
    static bool paste(EditorState &state, QString *problem = nullptr,
                      std::optional<QPointF> at = std::nullopt);
    // The move paste() applies to `strokes` in `frame` (see paste()).
    static QPointF pasteShift(const model::Frame *frame,
                              const std::vector<model::StrokeDataPtr> &strokes,
                              std::optional<QPointF> at);
    static constexpr qreal kPasteStep = 20.0; // canvas pixels per repeated paste
    static bool clipboardHasStrokes();
};

} // namespace finbook::ui
