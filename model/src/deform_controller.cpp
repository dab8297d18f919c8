#include <finbook/model/deform_controller.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/cut_out_layers.h>

#include <QMetaObject>

#include <algorithm>
#include <vector>

namespace finbook::model {

namespace {
constexpr std::size_t kRecentSetups = 24;
}

DeformController::DeformController(Document *document, QObject *parent)
    : QObject(parent)
    , m_doc(document)
{
    connect(m_doc, &Document::constraintsChanged, this, [this](Id id) {
        m_restoring.erase(id);
        refresh(id);
    });
    connect(m_doc, &Document::strokesChanged, this, [this](Id id) {
        m_restoring.erase(id);
        const auto it = m_states.find(id);
        refresh(id, it != m_states.end() && it->second.setup);
    });
    // Frames that arrive without a pose (generated in-betweens) get one like any edited object;
    // they usually share a key's drawing and rest definition, hence its factorization.
    connect(m_doc, &Document::framesInserted, this, [this](int first, int count) {
        // Many new poses at once (in-betweens): the paper's two steps now, converged soon.
        m_previewOnly = true;
        for (int i = first; i < first + count && i < m_doc->frameCount(); ++i)
            for (const StrokeGroup &g : m_doc->frameAt(i).groups)
                if (!g.rig.empty() && !g.deformed)
                    refresh(g.id);
        m_previewOnly = false;
    });
    connect(m_doc, &Document::documentReset, this, [this] {
        for (const auto &[id, state] : m_states)
            m_service.cancel(id);
        m_states.clear();
        m_recent.clear();
        m_unsettled.clear();
        m_restoring.clear();
        // A file stores a cut-out pose without its layers: solve it again, off this thread,
        // so the limbs are drawn over the body as before it was saved.
        for (int f = 0; f < m_doc->frameCount(); ++f)
            for (const StrokeGroup &g : m_doc->frameAt(f).groups)
                if (lacksCutOutLayers(g)) {
                    m_restoring.insert(g.id);
                    refresh(g.id);
                }
    });
    connect(&m_service, &PrecomputeService::busyChanged, this, &DeformController::busyChanged);
    connect(&m_service, &PrecomputeService::setupReady, this,
            [this](Id id, quint64, std::shared_ptr<const DeformSetup> setup) {
                setupReady(id, std::move(setup));
            });
    connect(&m_service, &PrecomputeService::setupFailed, this,
            [this](Id id, quint64, const QString &message) { setupFailed(id, message); });
    m_settleTimer.setSingleShot(true);
    m_settleTimer.setInterval(60);
    connect(&m_settleTimer, &QTimer::timeout, this, &DeformController::startConvergedSolves);
    m_pool.setMaxThreadCount(1);
}

DeformController::~DeformController()
{
    m_cancelConverged->store(true);
    m_pool.waitForDone();
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
    return it->second.vertices.rows() ? &it->second.vertices : &it->second.setup->meshVertices();
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
    if (!g || !g->isDeformed() || !s || !s->matches(*g, m_doc->settings().closeGap))
        return shown; // undeformed (or not yet solved): shown is rest
    return model::restPointFor(*s, *poseVertices(groupId), shown);
}

std::shared_ptr<const DeformSetup> DeformController::cachedSetup(const StrokeGroup &group) const
{
    const auto fits = [&](const std::shared_ptr<const DeformSetup> &s) {
        return s && sameSolverOptions(s->options, m_options) &&
               s->matches(group, m_doc->settings().closeGap);
    };
    if (const auto it = m_states.find(group.id); it != m_states.end() && fits(it->second.setup))
        return it->second.setup;
    for (const auto &s : m_recent)
        if (fits(s))
            return s;
    for (const auto &[id, state] : m_states)
        if (fits(state.setup))
            return state.setup;
    return nullptr;
}

void DeformController::setConverged()
{
    setSolverOptions(deform::ArapMethod::Refined, 0);
}

void DeformController::setExtraPasses(int passes)
{
    setSolverOptions(deform::ArapMethod::TwoStep, std::clamp(passes, 0, 10));
}

void DeformController::setSolverOptions(deform::ArapMethod method, int passes)
{
    if (m_options.method == method && m_options.extraPasses == passes)
        return;
    m_options.method = method;
    m_options.extraPasses = passes;
    // Meshes stay valid; every pinned object needs a new precompute with the new options.
    for (const Frame &f : m_doc->frames())
        for (const StrokeGroup &g : f.groups)
            if ((g.rig.kind() == RigKind::Pins || g.rig.kind() == RigKind::Skeleton) &&
                m_states.count(g.id))
                refresh(g.id);
}

std::shared_ptr<const MeshedObject> DeformController::cachedMesh(const MeshKey &key) const
{
    for (const auto &s : m_recent)
        if (s->meshed && s->key == key)
            return s->meshed;
    for (const auto &[id, state] : m_states)
        if (state.setup && state.setup->meshed && state.setup->key == key)
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
        m_unsettled.erase(groupId);
        return;
    }
    if (g->rig.empty() && !wantMesh) {
        m_service.cancel(groupId);
        if (auto it = m_states.find(groupId); it != m_states.end())
            it->second.waiting = false;
        return;
    }
    if (auto ready = cachedSetup(*g)) {
        solve(groupId, std::move(ready));
        return;
    }
    if (!g->hasContent())
        return;
    State &state = m_states[groupId];
    const MeshKey key = MeshKey::of(*g, m_doc->settings().closeGap);
    // Targets moving while the precompute runs need no new one: it solves them on arrival.
    if (!(state.waiting && state.pendingKey == key &&
          sameRestDefinition(state.pendingRest, g->rig))) {
        DeformJob job;
        job.groupId = groupId;
        job.key = key;
        job.meshed = cachedMesh(job.key);
        job.options = m_options;
        job.rig = g->rig.atRest();
        state.waiting = true;
        state.pendingKey = key;
        state.pendingRest = job.rig;
        m_service.request(std::move(job));
    }
    showPreview(*g);
}

void DeformController::showPreview(const StrokeGroup &group)
{
    // A cage whose coordinates are still on their way moves the drawing rigidly: the
    // similarity that best maps the rest corners onto the posed ones (least squares).
    const CageRig &cage = group.rig.cage;
    if (group.rig.kind() != RigKind::Cage || cage.posed.size() != cage.rest.size())
        return;
    const double n = double(cage.rest.size());
    QPointF restCentre, posedCentre;
    for (std::size_t i = 0; i < cage.rest.size(); ++i) {
        restCentre += cage.rest[i] / n;
        posedCentre += cage.posed[i] / n;
    }
    double dot = 0, cross = 0, norm = 0;
    for (std::size_t i = 0; i < cage.rest.size(); ++i) {
        const QPointF a = cage.rest[i] - restCentre, b = cage.posed[i] - posedCentre;
        dot += a.x() * b.x() + a.y() * b.y();
        cross += a.x() * b.y() - a.y() * b.x();
        norm += a.x() * a.x() + a.y() * a.y();
    }
    const double c = norm > 0 ? dot / norm : 1.0, s = norm > 0 ? cross / norm : 0.0;
    std::vector<std::size_t> offsets;
    Eigen::MatrixX2d points = restPoints(MeshKey::of(group, -1.0), offsets);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const double x = points(i, 0) - restCentre.x(), y = points(i, 1) - restCentre.y();
        points.row(i) << posedCentre.x() + c * x - s * y, posedCentre.y() + s * x + c * y;
    }
    if (points.allFinite())
        m_doc->setDeformed(group.id, strokesFromPoints(group, points));
}

void DeformController::solve(Id groupId, std::shared_ptr<const DeformSetup> setup)
{
    State &state = m_states[groupId];
    const bool newMesh = !state.setup || &state.setup->meshVertices() != &setup->meshVertices();
    // The pose shown belongs to this very setup (same mesh, same pinned vertices): a drag
    // event continues from it. The converged pose that follows is solved from the pins alone.
    const bool sameSetup = state.setup == setup && state.vertices.rows() > 0;
    state.waiting = false;
    state.setup = setup;
    const StrokeGroup *g = m_doc->group(groupId);
    if (g->rig.empty()) {
        state.vertices = setup->meshVertices();
    } else {
        // Pins that refine show the drag pose now and the converged one once they rest.
        const bool refines = setup->pins && setup->options.method == deform::ArapMethod::Refined;
        const PoseStage stage = !refines        ? PoseStage::Final
                                : m_previewOnly ? PoseStage::Preview
                                                : PoseStage::Drag;
        auto pose = solvePose(*setup, *g, stage, {}, sameSetup ? &state.vertices : nullptr);
        if (!pose) {
            state.error = pose.error();
            emit errorOccurred(groupId, state.error);
            return;
        }
        state.error.clear();
        ++m_settleGeneration[groupId]; // a converged solve of older targets is stale now
        if (refines) {
            m_unsettled.insert(groupId);
            m_settleTimer.start();
        } else {
            m_unsettled.erase(groupId);
        }
        // A reopened pose keeps its stored strokes unless it solves to them again.
        if (m_restoring.erase(groupId) > 0 && g->deformed &&
            !(pose->strokes && restoresLayers(*pose->strokes, *g->deformed)))
            state.vertices = std::move(pose->vertices);
        else
            storePose(groupId, std::move(*pose));
    }
    if (newMesh)
        emit meshChanged(groupId);
    emit poseSolved(groupId);
}

void DeformController::storePose(Id groupId, Pose pose)
{
    State &state = m_states[groupId];
    state.vertices = std::move(pose.vertices);
    m_doc->setDeformed(groupId, std::move(pose.strokes));
}

void DeformController::startConvergedSolves()
{
    for (Id id : m_unsettled) {
        const StrokeGroup *g = m_doc->group(id);
        const auto it = m_states.find(id);
        if (!g || it == m_states.end() || !it->second.setup)
            continue;
        // An immutable snapshot: the setup is shared and const, the group is a copy of
        // pointers and pins. The result is taken only if nothing changed meanwhile.
        auto setup = it->second.setup;
        StrokeGroup snapshot = *g;
        const quint64 generation = ++m_generation;
        m_settleGeneration[id] = generation;
        auto cancel = m_cancelConverged;
        m_pool.start([this, id, generation, setup, snapshot, cancel] {
            auto pose =
                solvePose(*setup, snapshot, PoseStage::Final, [cancel] { return cancel->load(); });
            if (!pose)
                return;
            QMetaObject::invokeMethod(
                this,
                [this, id, generation, p = std::move(*pose)]() mutable {
                    convergedSolved(id, generation, std::move(p));
                },
                Qt::QueuedConnection);
        });
    }
}

void DeformController::convergedSolved(Id groupId, quint64 generation, Pose pose)
{
    const auto it = m_settleGeneration.find(groupId);
    if (it == m_settleGeneration.end() || it->second != generation || !m_doc->group(groupId))
        return; // the targets moved on (or the object went) while it solved
    m_unsettled.erase(groupId);
    storePose(groupId, std::move(pose));
    emit poseSolved(groupId);
    reportFolds(groupId);
}

void DeformController::reportFolds(Id groupId)
{
    const auto it = m_states.find(groupId);
    if (it == m_states.end() || !it->second.setup || !it->second.setup->pins ||
        it->second.setup->options.method != deform::ArapMethod::Refined)
        return;
    const DeformSetup &setup = *it->second.setup;
    const int folds = deform::arapFlippedTriangles(setup.meshVertices(), setup.meshTriangles(),
                                                   it->second.vertices);
    if (folds > 0)
        emit foldsForced(groupId, folds);
}

void DeformController::settle()
{
    m_settleTimer.stop();
    const std::set<Id> pending = std::exchange(m_unsettled, {});
    for (Id id : pending) {
        const StrokeGroup *g = m_doc->group(id);
        const auto it = m_states.find(id);
        if (!g || it == m_states.end() || !it->second.setup ||
            !it->second.setup->matches(*g, m_doc->settings().closeGap))
            continue;
        ++m_settleGeneration[id]; // drops a converged solve still under way
        auto pose = solvePose(*it->second.setup, *g, PoseStage::Final);
        if (pose) {
            storePose(id, std::move(*pose));
            emit poseSolved(id);
            reportFolds(id);
        }
    }
}

void DeformController::setupReady(Id groupId, std::shared_ptr<const DeformSetup> setup)
{
    remember(setup);
    // Other objects waiting for the same drawing and rest definition (a reopened or new run of
    // frames duplicated from one key) take this setup instead of building their own.
    std::vector<Id> alike;
    for (const auto &[id, state] : m_states) {
        const StrokeGroup *other = id == groupId ? nullptr : m_doc->group(id);
        if (other && state.waiting && sameSolverOptions(setup->options, m_options) &&
            setup->matches(*other, m_doc->settings().closeGap))
            alike.push_back(id);
    }
    for (Id id : alike) {
        m_service.cancel(id);
        solve(id, setup);
    }
    const StrokeGroup *g = m_doc->group(groupId);
    if (!g)
        return;
    // The pins may have changed while the worker ran: use the setup only if it still fits
    // (else the newer request is already on its way).
    if (setup->matches(*g, m_doc->settings().closeGap))
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
