// The Skeleton panel: the four refinement sliders of the current object's skeleton (bone
// complexity, merge junctions, prune, collapse). Moving a slider re-refines the skeleton at
// once (a preview of every position); one slider drag is one undo step.
#pragma once

#include <finbook/model/skeleton/skeleton_rig.h>

#include <QWidget>

#include <array>

class QLabel;
class QSlider;

namespace finbook::ui {

class EditorState;

class SkeletonPanel : public QWidget {
    Q_OBJECT
public:
    // `compact`: the sliders in one row under short names (the Bone tool's options bar),
    // rather than a form with the hint (the Skeleton panel).
    explicit SkeletonPanel(EditorState *state, QWidget *parent = nullptr, bool compact = false);
    // complexity, merge, prune, collapse
    QSlider *slider(int index) const { return m_sliders[std::size_t(index)]; }

signals:
    void messagePosted(const QString &message);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void sync();
    void changed();

    EditorState *m_state;
    std::array<QSlider *, 4> m_sliders{};
    QLabel *m_hint = nullptr;
    int m_serial = 0;
    bool m_compact = false;
};

} // namespace finbook::ui
