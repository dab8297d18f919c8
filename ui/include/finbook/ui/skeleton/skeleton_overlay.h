// View → Show Skeleton: every object's skeleton over the current frame, posed as it is shown.
// Joints are circles scaled to their inscribed radius, bones lines, the root a square (a part
// joined to a character: a green diamond, with a dashed link to where it hangs); the
// current object's skeleton is coloured, the others grey. Locked joints are red with a ring
// (a pin head: they stay put). The Bone tool draws the same way, plus its selection and, in
// Edit Joints, dashed bones.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QObject>

#include <vector>

namespace finbook::ui {

class CanvasWidget;
class EditorState;

struct SkeletonLook {
    bool current = false;
    int highlightJoint = -1; // the joint or bone under the cursor / being dragged
    int selectedJoint = -1;  // the Bone tool's selected joint or bone
    bool editing = false;    // Edit Joints: the rest skeleton is being edited
};

// Paints one skeleton (its posed joints) in widget space.
void paintSkeleton(QPainter &painter, const QTransform &canvasToWidget,
                   const model::SkeletonRig &skeleton, const SkeletonLook &look);

class SkeletonOverlay : public QObject, public CanvasOverlay {
    Q_OBJECT
public:
    SkeletonOverlay(EditorState *state, CanvasWidget *canvas);
    bool isShown() const { return m_shown; }
    void setShown(bool shown);
    void paint(QPainter &painter, const QTransform &canvasToWidget) override;

signals:
    void shownChanged(bool shown);

private:
    EditorState *m_state;
    CanvasWidget *m_canvas;
    bool m_shown = false;
};

} // namespace finbook::ui
