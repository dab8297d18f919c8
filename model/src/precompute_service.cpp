#include <finbook/model/precompute_service.h>

namespace finbook::model {

// Lives on the worker thread; runs one job at a time, in request order.
class PrecomputeWorker : public QObject {
public:
    using Result = Expected<std::shared_ptr<const DeformSetup>, QString>;

    void run(const DeformJob &job, const std::shared_ptr<std::atomic_bool> &cancelled,
             const std::function<void(Result)> &done)
    {
        if (cancelled->load()) {
            done(unexpected(QStringLiteral("cancelled")));
            return;
        }
        done(buildDeformSetup(job, [&cancelled] { return cancelled->load(); }));
    }
};

PrecomputeService::PrecomputeService(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<Id>("finbook::model::Id");
    qRegisterMetaType<std::shared_ptr<const DeformSetup>>();
    m_worker = new PrecomputeWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread.setObjectName(QStringLiteral("finbook-precompute"));
    m_thread.start(QThread::LowPriority);
    m_timer.setSingleShot(true);
    m_timer.setInterval(8);
    connect(&m_timer, &QTimer::timeout, this, &PrecomputeService::dispatch);
}

PrecomputeService::~PrecomputeService()
{
    for (auto &[id, flag] : m_cancelFlags)
        flag->store(true);
    m_thread.quit();
    m_thread.wait();
}

quint64 PrecomputeService::request(DeformJob job)
{
    const Id groupId = job.groupId;
    const quint64 generation = ++m_generation;
    m_latest[groupId] = generation;
    if (auto it = m_cancelFlags.find(groupId); it != m_cancelFlags.end())
        it->second->store(true); // the running job for this object is stale now
    m_pending[groupId] = Pending{std::move(job), generation};
    if (!m_timer.isActive())
        m_timer.start();
    updateBusy();
    return generation;
}

void PrecomputeService::cancel(Id groupId)
{
    m_pending.erase(groupId);
    m_latest[groupId] = ++m_generation; // anything still running for it is dropped
    if (auto it = m_cancelFlags.find(groupId); it != m_cancelFlags.end()) {
        it->second->store(true); // the running job keeps its own reference to the flag
        m_cancelFlags.erase(it);
    }
    updateBusy();
}

quint64 PrecomputeService::latestGeneration(Id groupId) const
{
    const auto it = m_latest.find(groupId);
    return it == m_latest.end() ? 0 : it->second;
}

void PrecomputeService::dispatch()
{
    std::map<Id, Pending> batch;
    batch.swap(m_pending);
    for (auto &[groupId, pending] : batch) {
        auto flag = std::make_shared<std::atomic_bool>(false);
        m_cancelFlags[groupId] = flag;
        ++m_running;
        const Id id = groupId;
        const quint64 generation = pending.generation;
        auto done = [this, id, generation](PrecomputeWorker::Result result) {
            // Back to the service's thread; `this` outlives the worker thread (dtor waits).
            QMetaObject::invokeMethod(
                this,
                [this, id, generation, result = std::move(result)]() mutable {
                    finished(id, generation, std::move(result));
                },
                Qt::QueuedConnection);
        };
        QMetaObject::invokeMethod(
            m_worker,
            [worker = m_worker, job = std::move(pending.job), flag, done] {
                worker->run(job, flag, done);
            },
            Qt::QueuedConnection);
    }
}

void PrecomputeService::finished(Id groupId, quint64 generation,
                                 Expected<std::shared_ptr<const DeformSetup>, QString> result)
{
    --m_running;
    if (generation == latestGeneration(groupId)) {
        m_cancelFlags.erase(groupId);
        if (result)
            emit setupReady(groupId, generation, *result);
        else
            emit setupFailed(groupId, generation, result.error());
    }
    updateBusy();
}

void PrecomputeService::updateBusy()
{
    const bool busy = isBusy();
    if (busy == m_busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

} // namespace finbook::model
