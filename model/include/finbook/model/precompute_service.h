// Runs deformation precomputes (mesh, embedding, ARAP factorizations) on a worker thread.
//
// Jobs are immutable snapshots; results come back as shared_ptr<const DeformSetup> on the
// GUI thread. A request supersedes every earlier one for the same object: the earlier job is
// cancelled (its callback polls an atomic flag) and, should it finish anyway, its result is
// dropped by the generation check. Requests arriving within a short interval are coalesced,
// so adding pins in quick succession factorizes once.
#pragma once

#include <finbook/model/deform_setup.h>

#include <QObject>
#include <QThread>
#include <QTimer>

#include <atomic>
#include <map>
#include <memory>

namespace finbook::model {

class PrecomputeWorker;

class PrecomputeService : public QObject {
    Q_OBJECT
public:
    explicit PrecomputeService(QObject *parent = nullptr);
    // Cancels what runs, quits the thread and waits for it.
    ~PrecomputeService() override;

    // Queues `job`; returns its generation (increasing per service).
    quint64 request(DeformJob job);
    // Forgets pending work for an object (deleted, or no longer needs a setup).
    void cancel(Id groupId);

    bool isBusy() const { return !m_pending.empty() || m_running > 0; }
    quint64 latestGeneration(Id groupId) const;
    // Milliseconds during which further requests join the same dispatch (default 8).
    void setCoalesceInterval(int ms) { m_timer.setInterval(ms); }

signals:
    void setupReady(finbook::model::Id groupId, quint64 generation,
                    std::shared_ptr<const finbook::model::DeformSetup> setup);
    void setupFailed(finbook::model::Id groupId, quint64 generation, const QString &message);
    void busyChanged(bool busy);

private:
    struct Pending {
        DeformJob job;
        quint64 generation;
    };
    void dispatch();
    void finished(Id groupId, quint64 generation,
                  Expected<std::shared_ptr<const DeformSetup>, QString> result);
    void updateBusy();

    QThread m_thread;
    PrecomputeWorker *m_worker = nullptr;
    QTimer m_timer;
    std::map<Id, Pending> m_pending;
    std::map<Id, quint64> m_latest;
    std::map<Id, std::shared_ptr<std::atomic_bool>> m_cancelFlags;
    quint64 m_generation = 0;
    int m_running = 0;
    bool m_busy = false;
};

} // namespace finbook::model
