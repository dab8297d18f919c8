// Edits on the cels picked in the dope sheet (EditorState::selectedCels), shared by the sheet
// and the Edit and Layer menus: cut, copy, paste, delete, and time inserted or deleted on the
// picked cels' layers. Each edit is one undo step.
//
// Copied cels stay in this process (their objects, rigs and poses as they are); the system
// clipboard gets a token naming them, so whatever is copied last, cels or strokes, is what
// Paste pastes.
#pragma once

#include <finbook/model/types.h>

#include <QCoreApplication>

#include <vector>

namespace finbook::ui {

class EditorState;

inline constexpr char kCelsMimeType[] = "application/x-finbook-cels";

class CelEditing {
    Q_DECLARE_TR_FUNCTIONS(CelEditing)
public:
    // The picked cels, one row per layer (back to front), each row in the layer's order.
    static std::vector<std::vector<model::Frame>> pickedRows(const EditorState &state);

    static bool copy(const EditorState &state);
    static bool cut(EditorState &state);
    // Removes the picked cels; what follows moves earlier. False when nothing was removed.
    static bool remove(EditorState &state);
    // The copied rows into the current layer (and the layers above it), at the boundary
    // between cels nearest the playhead. False with `problem` set when nothing could go.
    static bool paste(EditorState &state, QString *problem = nullptr);
    static bool clipboardHasCels();

    // Layer → Insert Time / Delete Time: on the picked cels' layers, as many ticks as they
    // span, from where the first starts; with none picked, one tick at the playhead on the
    // current layer.
    static bool insertTime(EditorState &state);
    static bool deleteTime(EditorState &state);
};

} // namespace finbook::ui
