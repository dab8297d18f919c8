// Frame → Generate In-betweens…: how many frames go between two keys and how they are spaced,
// what will be interpolated and what held, with the middle in-between previewed live.
//
// The dialog never changes the document. Its preview is a planned frame (planned and) posed on a
// worker thread (solveInbetweenPoses, one factorization per object for the dialog's lifetime: the
// first pose of a 2.4k-vertex object took about 70 ms, which froze the controls when it ran
// on the GUI thread) and handed to the preview sink (the canvas) when it is ready; a change
// made meanwhile is posed after it, only the newest shown. The sink gets std::nullopt when
// the dialog closes. The caller pushes InsertInbetweensCommand with count(), options() and
// fits() on Accepted.
//
// Objects the two keys show drawn differently (two separate drawings, not one posed) are fitted
// one onto the other on another worker thread when the dialog opens (Between Drawings,
// model/inbetween/between_drawings.h); OK waits for it. Each is then carried from the first
// key's lines to the second's, or, unchecked or unfitted, switches over half way. The fit is
// shown (BetweenFitView) and can be corrected with correspondence pins, refitted live on a
// worker thread; Ctrl+Z and Ctrl+Shift+Z undo and redo pin changes inside the dialog.
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/model/document.h>
#include <finbook/model/inbetween/between_drawings.h>
#include <finbook/model/inbetween/inbetween_plan.h>
#include <finbook/model/inbetween/inbetween_solve.h>

#include <QDialog>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QSpinBox;
class QThread;
class QUndoStack;

namespace finbook::ui {

class BetweenFitView;

class InbetweenDialog : public QDialog {
    Q_OBJECT
public:
    using PreviewSink = std::function<void(std::optional<model::Frame>)>;

    // `firstKey` and `secondKey` in either order (the earlier frame is the first key).
    InbetweenDialog(model::Document *document, model::Id firstKey, model::Id secondKey,
                    const deform::ArapOptions &options, PreviewSink preview,
                    QWidget *parent = nullptr);
    ~InbetweenDialog() override;

    model::Id firstKey() const { return m_first; }
    model::Id secondKey() const { return m_second; }
    int count() const;
    model::InbetweenOptions options() const;
    // The fits of the objects drawn differently, when they are to be used (empty otherwise).
    model::DrawingFits fits() const;
    bool fitting() const { return m_fitter != nullptr || m_refitter != nullptr; }
    // Puts `pins` on the fit of the object at `index` of the keys and refits (the undo steps
    // of the pins call it).
    void applyPins(int index, const std::vector<model::BetweenPin> &pins);
    // The middle in-between as previewed now (nullopt if its pose could not be solved, and
    // before the first one is ready); posing() while a newer one is being solved.
    const std::optional<model::Frame> &previewFrame() const { return m_preview; }
    bool posing() const { return m_worker != nullptr; }

    // The in-betweens made when OK was pressed with drawings carried onto others (made on a
    // worker thread: OK waits for them); nullopt otherwise, and the caller plans them.
    const std::optional<model::InbetweenPlan> &plannedFrames() const { return m_planned; }

    void accept() override;
    void done(int result) override;

private:
    QWidget *buildControls();
    void updatePlan();
    QString describe(const model::InbetweenObjectReport &object) const;
    struct PreviewJob;
    void showPreview(PreviewJob &job);
    void startFitting();
    void requestRefit(int index, std::vector<model::BetweenPin> pins);
    void showFitOf(int index);

    model::Document *m_doc;
    model::Id m_first;
    model::Id m_second;
    deform::ArapOptions m_arap;
    PreviewSink m_sink;
    model::DeformSetupCache m_setups;
    std::optional<model::Frame> m_preview;
    QThread *m_worker = nullptr; // posing the preview
    bool m_replan = false;       // the options changed while it did
    QThread *m_fitter = nullptr; // fitting the drawings that differ
    model::KeyFits m_fits;
    QThread *m_refitter = nullptr; // refitting with changed correspondence pins
    std::optional<std::pair<int, std::vector<model::BetweenPin>>> m_pendingRefit;
    QUndoStack *m_pinUndo = nullptr;
    int m_shownFit = -1;          // the object whose fit the view shows
    QThread *m_planner = nullptr; // making the in-betweens after OK
    std::optional<model::InbetweenPlan> m_planned;
    QSpinBox *m_count = nullptr;
    QComboBox *m_spacing = nullptr;
    QSlider *m_favour = nullptr;
    QCheckBox *m_arcs = nullptr;
    QCheckBox *m_between = nullptr;
    BetweenFitView *m_fitView = nullptr;
    QComboBox *m_fitObject = nullptr;
    QLabel *m_fitLabel = nullptr;
    QPushButton *m_ok = nullptr;
    QListWidget *m_objects = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace finbook::ui
