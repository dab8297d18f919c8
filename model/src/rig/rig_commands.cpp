#include "../command_text.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/rig/rig_commands.h>

#include <algorithm>

namespace finbook::model {

bool sameRestDefinition(const Rig &a, const Rig &b)
{
    if (a.kind() != b.kind() || a.pins.size() != b.pins.size() || a.cage.rest != b.cage.rest ||
        !a.skeleton.sameRest(b.skeleton))
        return false;
    return std::equal(a.pins.begin(), a.pins.end(), b.pins.begin(),
                      [](const Pin &p, const Pin &q) { return p.rest == q.rest; });
}

SetRigCommand::SetRigCommand(Document *doc, Id groupId, Rig rig, const QString &text,
                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_new(std::move(rig))
{
    setText(text);
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig == m_new)
        setObsolete(true);
}

void SetRigCommand::redo()
{
    const StrokeGroup *g = m_doc->group(m_groupId);
    if (isObsolete() || !g)
        return;
    m_old = g->rig;
    m_oldDeformed = g->deformed;
    m_doc->setRig(m_groupId, m_new);
}

void SetRigCommand::undo()
{
    if (isObsolete() || !m_doc->group(m_groupId))
        return;
    m_doc->setRig(m_groupId, m_old);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
}

PoseRigCommand::PoseRigCommand(Document *doc, Id groupId, Rig posed, int dragSerial,
                               const QString &text, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_serial(dragSerial)
    , m_new(std::move(posed))
{
    setText(text);
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !sameRestDefinition(g->rig, m_new) || g->rig.empty())
        setObsolete(true);
    else
        m_old = g->rig;
}

bool PoseRigCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const PoseRigCommand *>(other);
    if (o->m_groupId != m_groupId || o->m_serial != m_serial || o->isObsolete())
        return false;
    m_new = o->m_new;
    return true;
}

void PoseRigCommand::redo()
{
    if (!isObsolete() && m_doc->group(m_groupId))
        m_doc->setRig(m_groupId, m_new);
}

void PoseRigCommand::undo()
{
    if (!isObsolete() && m_doc->group(m_groupId))
        m_doc->setRig(m_groupId, m_old);
}

ResetPoseCommand::ResetPoseCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Reset Pose"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !g->rig.isPosed())
        setObsolete(true);
    else
        m_before = g->rig;
}

void ResetPoseCommand::redo()
{
    if (!isObsolete())
        m_doc->setRig(m_groupId, m_before.atRest());
}

void ResetPoseCommand::undo()
{
    if (!isObsolete())
        m_doc->setRig(m_groupId, m_before);
}

AppliedPose applyPoseToDrawing(const StrokeGroup &group, double closeGap,
                               const std::function<Id()> &newId)
{
    // The baked strokes keep their ids: they are the same strokes, redrawn (a line that a
    // cut-out limb hid in the middle becomes its parts, shown, hidden and shown again, the
    // first part shown with its id; the hidden parts stay as hidden lines).
    std::vector<Stroke> strokes = bakedStrokes(group, closeGap, newId, HiddenLines::KeepUnseen);
    // A gap the pose showed closed stays closed (by a line of no ink) where the baked lines
    // alone would leave it open, or close it a little further along a line (GapMatch::Exact,
    // tried where it draws in more closers than GapMatch::Near); each also matched again with
    // the kept closers in (`rematch`), tried where that draws in more.
    using Ways = std::vector<std::vector<Stroke>>;
    const auto withKeptGaps = [&](const std::vector<Stroke> &lines) {
        std::pair<Ways, Ways> out; // as matched, and matched again
        auto &[ways, rematchedWays] = out;
        const auto add = [&](Ways &to, std::vector<Stroke> closers) {
            to.push_back(lines);
            to.back().insert(to.back().end(), std::make_move_iterator(closers.begin()),
                             std::make_move_iterator(closers.end()));
        };
        std::size_t nearCount = 0;
        for (const GapMatch match : {GapMatch::Near, GapMatch::Exact}) {
            std::vector<Stroke> rematched;
            std::vector<Stroke> closers =
                keptGapClosers(group, lines, closeGap, newId, match, &rematched);
            if (match == GapMatch::Exact && closers.size() == nearCount)
                break;
            nearCount = closers.size();
            add(ways, std::move(closers));
            if (!rematched.empty())
                add(rematchedWays, std::move(rematched));
        }
        return out;
    };
    // A cut-out piece's colour ends at its cut, where no line is: a line of no ink keeps the
    // baked regions ending there too (added before the kept gaps: a region they close, a
    // body, no longer lets gap closing close a gap inside it, an eye, that the pose showed
    // closed). Those lines do not find every region of every drawing, so the bake keeps them
    // only where they keep more of the colours the pose showed than the baked lines alone.
    // Tried in this order, the first of equals kept: without the cut lines, with them, then the
    // same with the gaps matched exactly, then both rematched.
    std::vector<Stroke> cut = cutOutClosers(group, strokes, closeGap, newId);
    std::pair<Ways, Ways> without = withKeptGaps(strokes);
    std::pair<Ways, Ways> withCuts;
    if (!cut.empty()) {
        strokes.insert(strokes.end(), cut.begin(), cut.end());
        withCuts = withKeptGaps(strokes);
    }
    Ways ways;
    std::size_t firstRematched = 0;
    for (const bool rematched : {false, true}) {
        Ways &a = rematched ? without.second : without.first;
        Ways &b = rematched ? withCuts.second : withCuts.first;
        for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i)
            for (Ways *set : {&a, &b})
                if (i < set->size())
                    ways.push_back(std::move((*set)[i]));
        if (!rematched)
            firstRematched = ways.size();
    }
    // Where the baked faces of a way still join colours the pose showed apart, lines of no ink
    // along the edge between them as painted: the seams, the seams left off the ink, or the
    // seams across thin ink (outside every face), each with the gaps closed now kept closed or
    // not, whichever keeps most of what was shown (and only if that is more than without
    // them). Parts of faces only a little wider than the pen are tried too when the wider ones
    // leave colours apart (a wedge under a curl: its seam may make a face the regions keep, or
    // one they merge away, so only the agreement can tell). A way is judged with its seams (a
    // closer drawn in exactly may lose a colour that only its seams bring back): the ways are
    // taken best first as they stand, and the search ends once all but a thousandth of what
    // the pose showed is kept (each further way costs as much again, on the UI thread).
    constexpr double kKeptEnough = 0.999;
    const ShownPose shown(group, closeGap); // painted once for every bake weighed
    std::vector<std::pair<FillAgreement, std::size_t>> order;
    for (std::size_t i = 0; i < ways.size(); ++i)
        order.emplace_back(ways.size() > 1 ? shownFillAgreement(shown, ways[i]) : FillAgreement{},
                           i);
    std::stable_sort(order.begin(), order.end(),
                     [](const auto &a, const auto &b) { return a.first > b.first; });
    // A way matched again is weighed with its seams only when it stands better than every
    // way as first matched (it is one of them with a few closers more, and each weighing
    // costs a regions computation or more).
    FillAgreement bestFirstMatched{-1.0, -1.0};
    for (const auto &[agreement, i] : order)
        if (i < firstRematched)
            bestFirstMatched = std::max(bestFirstMatched, agreement);
    FillAgreement best{-1.0, -1.0};
    std::vector<Stroke> chosen;
    const auto consider = [&](const std::vector<Stroke> &lines, const FillAgreement &agreement) {
        if (agreement > best) {
            best = agreement;
            chosen = lines;
        }
    };
    for (const auto &taken : order) {
        if (best.atLeast(kKeptEnough))
            break;
        if (taken.second >= firstRematched && !(taken.first > bestFirstMatched))
            continue;
        const std::vector<Stroke> &way = ways[taken.second];
        for (const double widerThanPen : {kSeamWiderThanPen, 1.0}) {
            if (best.whole())
                break;
            const ShownColourSeams seams = shownColourSeams(shown, way, newId, widerThanPen);
            consider(way, seams.bakedAgreement);
            for (const std::vector<Stroke> *set :
                 {&seams.seams, &seams.seamsOffInk, &seams.seamsAcrossInk}) {
                if (set->empty() || best.whole()) // nothing later could be better
                    continue;
                std::vector<Stroke> with = way;
                with.insert(with.end(), set->begin(), set->end());
                for (int keep = 0; keep < (seams.keptClosures.empty() ? 1 : 2) && !best.whole();
                     ++keep) {
                    if (keep)
                        with.insert(with.end(), seams.keptClosures.begin(),
                                    seams.keptClosures.end());
                    consider(with, shownFillAgreement(shown, with));
                }
            }
        }
    }
    strokes = std::move(chosen);
    std::vector<Fill> fills = fillsAfterBake(shown, strokes);
    std::shared_ptr<const ObjectPicture> picture = group.picture;
    if (picture) {
        // A pose that cannot be kept as a picture (folded to nothing, too large) leaves it
        // at rest rather than losing it.
        if (auto baked = bakedPicture(group))
            picture = std::move(*baked);
    }
    return {std::move(strokes), std::move(fills), std::move(picture)};
}

ApplyPoseCommand::ApplyPoseCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Apply Pose to Drawing"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !g->isDeformed() || g->deformed->strokes.size() != g->strokes.size()) {
        setObsolete(true);
        return;
    }
    m_oldStrokes = g->strokes;
    m_oldRig = g->rig;
    m_oldDeformed = g->deformed;
    const auto newId = [doc] { return doc->allocateId(); };
    AppliedPose applied = applyPoseToDrawing(*g, doc->settings().closeGap, newId);
    m_newStrokes = std::move(applied.strokes);
    m_oldFills = g->fills;
    m_newFills = std::move(applied.fills);
    m_oldPicture = g->picture;
    m_newPicture = std::move(applied.picture);
}

void ApplyPoseCommand::redo()
{
    if (isObsolete())
        return;
    m_doc->setStrokes(m_groupId, m_newStrokes);
    if (m_newPicture != m_oldPicture)
        m_doc->setPicture(m_groupId, m_newPicture);
    if (m_newFills != m_oldFills)
        m_doc->setFills(m_groupId, m_newFills);
    m_doc->setRig(m_groupId, m_oldRig.rebased());
}

void ApplyPoseCommand::undo()
{
    if (isObsolete())
        return;
    m_doc->setStrokes(m_groupId, m_oldStrokes);
    if (m_newPicture != m_oldPicture)
        m_doc->setPicture(m_groupId, m_oldPicture);
    if (m_newFills != m_oldFills)
        m_doc->setFills(m_groupId, m_oldFills);
    m_doc->setRig(m_groupId, m_oldRig);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
}

} // namespace finbook::model
