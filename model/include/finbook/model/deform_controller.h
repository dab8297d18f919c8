// Keeps every pinned object's pose solved while the document changes.
//
// When an object's pins or rest strokes change, the controller looks for a DeformSetup that
// still fits (the object's own, or one of a recently used few: a duplicated frame shares its
// source's drawing and pins, so it shares the factorization too). With one it solves on the
// spot — one back-substitution pair, well under a millisecond for typical objects — and stores
// the pose in the document; without one it asks the PrecomputeService and solves when the
// setup arrives, with whatever the pins' targets are by then.
#pragma once

#include <finbook/model/document.h>
#include <finbook/model/precompute_service.h>

#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <atomic>
#include <deque>
#include <map>
#include <set>

namespace finbook::model {

class DeformController : public QObject {
    Q_OBJECT
public:
    explicit DeformController(Document *document, QObject *parent = nullptr);
    // Cancels converged solves still running and waits for them.
    ~DeformController() override;

    PrecomputeService *service() { return &m_service; }
    bool isBusy() const { return m_service.isBusy(); }
    bool isWaiting(Id groupId) const;

    // Starts whatever an object needs before its pins can be dragged (no-op when ready).
    void prepare(Id groupId);
    // Asks for an object's mesh without pins (View → Show Mesh).
    void requestMesh(Id groupId);

    // The setup an object is solved with now, or null; its current deformed vertices.
    const DeformSetup *setup(Id groupId) const;
    const Eigen::MatrixX2d *poseVertices(Id groupId) const;
    QString lastError(Id groupId) const;

    // How pins solve. Converged (the default): while a pin moves, as many refinement passes
    // as fit the drag budget; shortly after it stops (and before anything is saved, exported
    // or baked: settle()), the converged pose. Otherwise Igarashi's two steps plus `passes`
    // extra local/global passes (0 = the paper's method exactly). Changing it re-prepares
    // every pinned object of the document.
    bool converged() const { return m_options.method == deform::ArapMethod::Refined; }
    void setConverged();
    int extraPasses() const { return m_options.extraPasses; }
    void setExtraPasses(int passes);

    // Whether a converged pose is still to come for an object.
    bool isSettling(Id groupId) const { return m_unsettled.count(groupId) > 0; }
    // Solves every pending converged pose now, on this thread: what is stored is final.
    void settle();
    // Milliseconds of stillness after which the converged pose is solved (default 60).
    void setSettleDelay(int ms) { m_settleTimer.setInterval(ms); }

    // Where on the rest drawing a pin put at `shown` (canvas px, as displayed) belongs.
    QPointF restPointFor(Id groupId, QPointF shown) const;

signals:
    void busyChanged(bool busy);
    void meshChanged(finbook::model::Id groupId);
    void poseSolved(finbook::model::Id groupId);
    void errorOccurred(finbook::model::Id groupId, const QString &message);
    // A converged pin pose was stored that turns `triangles` triangles of the object's mesh
    // inside out: folds the pins force, where they leave the mesh no room (deform/arap.h keeps
    // a fold only where the converged pose without repair has it too). The pose is kept and
    // shown as it is; the window says so.
    void foldsForced(finbook::model::Id groupId, int triangles);

private:
    struct State {
        std::shared_ptr<const DeformSetup> setup;
        Eigen::MatrixX2d vertices; // deformed mesh vertices for `setup`
        QString error;
        bool waiting = false;
        // What the request on its way was made for: while only targets change, it still fits.
        MeshKey pendingKey;
        Rig pendingRest;
    };
    void showPreview(const StrokeGroup &group);
    void refresh(Id groupId, bool wantMesh = false);
    void solve(Id groupId, std::shared_ptr<const DeformSetup> setup);
    std::shared_ptr<const DeformSetup> cachedSetup(const StrokeGroup &group) const;
    std::shared_ptr<const MeshedObject> cachedMesh(const MeshKey &key) const;
    void remember(std::shared_ptr<const DeformSetup> setup);
    void setupReady(Id groupId, std::shared_ptr<const DeformSetup> setup);
    void setupFailed(Id groupId, const QString &message);
    void setSolverOptions(deform::ArapMethod method, int passes);
    void startConvergedSolves();
    void convergedSolved(Id groupId, quint64 generation, Pose pose);
    void storePose(Id groupId, Pose pose);
    void reportFolds(Id groupId);

    Document *m_doc;
    PrecomputeService m_service;
    std::map<Id, State> m_states;
    std::deque<std::shared_ptr<const DeformSetup>> m_recent; // most recent first
    deform::ArapOptions m_options;
    // Objects showing a drag pose whose converged pose is pending, and the generation of
    // the converged solve each may accept.
    std::set<Id> m_unsettled;
    std::map<Id, quint64> m_settleGeneration;
    quint64 m_generation = 0;
    bool m_previewOnly = false; // solving a batch of inserted frames
    // Objects of a document just opened whose cut-out pose is solved again for its layers
    // (skeleton/cut_out_layers.h): the result is taken only where it is the stored pose.
    std::set<Id> m_restoring;
    std::shared_ptr<std::atomic_bool> m_cancelConverged = std::make_shared<std::atomic_bool>();
    QTimer m_settleTimer;
    QThreadPool m_pool;
};

} // namespace finbook::model
