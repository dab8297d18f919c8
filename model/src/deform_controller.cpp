#include <finbook/model/deform_controller.h>

#include <algorithm>

namespace finbook::model {

namespace {
constexpr std::size_t kRecentSetups = 24;
}

DeformController::DeformController(Document *document, QObject *parent)
    : QObject(parent)
    , m_doc(document)
{
    connect(m_doc, &Document::constraintsChanged, this, [this](Id id) { refresh(id); });
    connect(m_doc, &Document::strokesChanged, this, [this](Id id) {
        const auto it = m_states.find(id);
        refresh(id, it != m_states.end() && it->second.setup);
    });
    connect(m_doc, &Document::documentReset, this, [this] {
        for (const auto &[id, state] : m_states)
            m_service.cancel(id);
        m_states.clear();
        m_recent.clear();
    });
    connect(&m_service, &PrecomputeService::busyChanged, this, &DeformController::busyChanged);
    connect(&m_service, &PrecomputeService::setupReady, this,
            [this](Id id, quint64, std::shared_ptr<const DeformSetup> setup) {
                setupReady(id, std::move(setup));
            });
    connect(&m_service, &PrecomputeService::setupFailed, this,
            [this](Id id, quint64, const QString &message) { setupFailed(id, message); });
}

bool DeformController::isWaiting(Id groupId) const
{
    const auto it = m_states.find(groupId);
    return it != m_states.end() && it->second.waiting;
}

void DeformController::prepare(Id groupId)
{
    refresh(groupId);
}
void DeformController::requestMesh(Id groupId)
{
    refresh(groupId, true);
}

const DeformSetup *DeformController::setup(Id groupId) const
{
    const auto it = m_states.find(groupId);
    return it == m_states.end() ? nullptr : it->second.setup.get();
}

const Eigen::MatrixX2d *DeformController::poseVertices(Id groupId) const
{
    const auto it = m_states.find(groupId);
    if (it == m_states.end() || !it->second.setup)
        return nullptr;
    return it->second.vertices.rows() ? &it->second.vertices : &it->second.setup->meshed->mesh.V;
}

QString DeformController::lastError(Id groupId) const
{
    const auto it = m_states.find(groupId);
    return it == m_states.end() ? QString() : it->second.error;
}

QPointF DeformController::restPointFor(Id groupId, QPointF shown) const
{
    const StrokeGroup *g = m_doc->group(groupId);
    const DeformSetup *s = setup(groupId);
    if (!g || !g->isDeformed() || !s || !s->matches(*g))
        return shown; // undeformed (or not yet solved): shown is rest
    return model::restPointFor(*s, *poseVertices(groupId), shown);
}

std::shared_ptr<const DeformSetup> DeformController::cachedSetup(const StrokeGroup &group) const
{
    const auto fits = [&](const std::shared_ptr<const DeformSetup> &s) {
        return s && s->extraPasses == m_options.extraPasses && s->matches(group);
    };
    if (const auto it = m_states.find(group.id); it != m_states.end() && fits(it->second.setup))
        return it->second.setup;
    for (const auto &s : m_recent)
        if (fits(s))
            return s;
    return nullptr;
}

void DeformController::setExtraPasses(int passes)
{
    passes = std::clamp(passes, 0, 10);
    if (passes == m_options.extraPasses)
        return;
    m_options.extraPasses = passes;
    // Meshes stay valid; every pinned object needs a new precompute with the new options.
    for (const Frame &f : m_doc->frames())
        for (const StrokeGroup &g : f.groups)
            if (!g.pins.empty() && m_states.count(g.id))
                refresh(g.id);
}

std::shared_ptr<const MeshedObject> DeformController::cachedMesh(const MeshKey &key) const
{
    for (const auto &s : m_recent)
        if (s->key == key)
            return s->meshed;
    for (const auto &[id, state] : m_states)
        if (state.setup && state.setup->key == key)
            return state.setup->meshed;
    return nullptr;
}

void DeformController::remember(std::shared_ptr<const DeformSetup> setup)
{
    std::erase(m_recent, setup);
    m_recent.push_front(std::move(setup));
    if (m_recent.size() > kRecentSetups)
        m_recent.pop_back();
}

void DeformController::refresh(Id groupId, bool wantMesh)
{
    const StrokeGroup *g = m_doc->group(groupId);
    if (!g) {
        m_service.cancel(groupId);
        m_states.erase(groupId);
        return;
    }
    if (g->pins.empty() && !wantMesh) {
        m_service.cancel(groupId);
        if (auto it = m_states.find(groupId); it != m_states.end())
            it->second.waiting = false;
        return;
    }
    if (auto ready = cachedSetup(*g)) {
        solve(groupId, std::move(ready));
        return;
    }
    if (g->strokes.empty())
        return;
    DeformJob job;
    job.groupId = groupId;
    job.key = MeshKey::of(*g);
    job.meshed = cachedMesh(job.key);
    job.options = m_options;
    job.pinRest.resize(Eigen::Index(g->pins.size()), 2);
    for (std::size_t i = 0; i < g->pins.size(); ++i) {
        job.pinRest.row(Eigen::Index(i)) << g->pins[i].rest.x(), g->pins[i].rest.y();
    }
    m_states[groupId].waiting = true;
    m_service.request(std::move(job));
}

void DeformController::solve(Id groupId, std::shared_ptr<const DeformSetup> setup)
{
    State &state = m_states[groupId];
    const bool newMesh = !state.setup || state.setup->meshed != setup->meshed;
    state.waiting = false;
    state.setup = setup;
    const StrokeGroup *g = m_doc->group(groupId);
    if (g->pins.empty()) {
        state.vertices = setup->meshed->mesh.V;
    } else {
        auto pose = solvePose(*setup, *g);
        if (!pose) {
            state.error = pose.error();
            emit errorOccurred(groupId, state.error);
            return;
        }
        state.error.clear();
        state.vertices = std::move(pose->vertices);
        m_doc->setDeformed(groupId, std::move(pose->strokes));
    }
    if (newMesh)
        emit meshChanged(groupId);
    emit poseSolved(groupId);
}

void DeformController::setupReady(Id groupId, std::shared_ptr<const DeformSetup> setup)
{
    remember(setup);
    const StrokeGroup *g = m_doc->group(groupId);
    if (!g)
        return;
    // The pins may have changed while the worker ran: use the setup only if it still fits
    // (else the newer request is already on its way).
    if (setup->matches(*g) || (g->pins.empty() && setup->key == MeshKey::of(*g)))
        solve(groupId, std::move(setup));
}

void DeformController::setupFailed(Id groupId, const QString &message)
{
    State &state = m_states[groupId];
    state.waiting = false;
    state.error = message;
    emit errorOccurred(groupId, message);
}

} // namespace finbook::model
