#include <finbook/model/deform_setup.h>
#include <finbook/model/inbetween/between_drawings.h>
#include <finbook/model/inbetween/inbetween_plan.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace finbook::model {

namespace {

constexpr double kSwitchOver = 0.5; // objects of one key only: first key's before, second's from

bool sameDrawing(const StrokeGroup &a, const StrokeGroup &b)
{
    return a.hasContent() && MeshKey::of(a, -1.0) == MeshKey::of(b, -1.0);
}

ObjectFate pairFate(const StrokeGroup &a, const StrokeGroup &b)
{
    if (canInterpolateRigs(a.rig, b.rig))
        return ObjectFate::Interpolated;
    return a.rig.empty() && b.rig.empty() ? ObjectFate::HeldNoRig : ObjectFate::HeldRigDiffers;
}

// The fate of the object at `index` of each key, and the report, in one pass.
struct Matching {
    std::vector<std::optional<ObjectFate>> pairs; // per index < min(sizes); empty = not one object
    std::vector<InbetweenObjectReport> report;
};

const DrawingFit *fitAt(const DrawingFits &fits, std::size_t i)
{
    return i < fits.size() ? fits[i].get() : nullptr;
}

// A fit made for these two objects (by id: the same keys).
bool fitsPair(const DrawingFit *fit, const StrokeGroup &a, const StrokeGroup &b)
{
    return fit && fit->a.id == a.id && fit->b.id == b.id;
}

Matching matchObjects(const Frame &first, const Frame &second, const DrawingFits &fits)
{
    Matching m;
    const std::size_t common = std::min(first.groups.size(), second.groups.size());
    m.pairs.resize(common);
    std::vector<InbetweenObjectReport> secondOnly;
    for (std::size_t i = 0; i < first.groups.size(); ++i) {
        const StrokeGroup &a = first.groups[i];
        InbetweenObjectReport r{a.name, int(i), -1, ObjectFate::FirstKeyOnly, a.rig.kind()};
        if (i < common && sameDrawing(a, second.groups[i])) {
            m.pairs[i] = pairFate(a, second.groups[i]);
            r.secondIndex = int(i);
            r.fate = *m.pairs[i];
        } else if (i < common && fitsPair(fitAt(fits, i), a, second.groups[i])) {
            m.pairs[i] = ObjectFate::Fitted;
            r.secondIndex = int(i);
            r.fate = ObjectFate::Fitted;
            r.rig = RigKind::None;
        }
        m.report.push_back(r);
    }
    for (std::size_t i = 0; i < second.groups.size(); ++i)
        if (i >= common || !m.pairs[i]) {
            const StrokeGroup &b = second.groups[i];
            secondOnly.push_back({b.name, -1, int(i), ObjectFate::SecondKeyOnly, b.rig.kind()});
        }
    m.report.insert(m.report.end(), secondOnly.begin(), secondOnly.end());
    return m;
}

Frame inbetweenFrame(const Frame &first, const Frame &second, const Matching &m, double t,
                     TargetPath path, const DrawingFits &fits)
{
    const bool early = t < kSwitchOver;
    Frame out;
    out.id = first.id;
    out.hold = first.hold;
    const Frame &base = early ? first : second;
    out.groups.reserve(base.groups.size());
    for (std::size_t i = 0; i < base.groups.size(); ++i) {
        if (i >= m.pairs.size() || !m.pairs[i]) {
            out.groups.push_back(base.groups[i]); // one key only: held as it is there
            continue;
        }
        if (*m.pairs[i] == ObjectFate::Fitted) {
            // The first key's drawing carried, and in the cross-fade the second's over it.
            StrokeGroup g = betweenDrawing(*fitAt(fits, i), t);
            g.id = first.groups[i].id;
            g.name = first.groups[i].name;
            g.visible = first.groups[i].visible;
            g.locked = first.groups[i].locked;
            out.groups.push_back(std::move(g));
            if (std::optional<StrokeGroup> in = fadingInDrawing(*fitAt(fits, i), t)) {
                in->id = second.groups[i].id;
                in->name = second.groups[i].name;
                in->visible = second.groups[i].visible;
                in->locked = second.groups[i].locked;
                out.groups.push_back(std::move(*in));
            }
            continue;
        }
        StrokeGroup g = first.groups[i]; // one object in both keys: the first key's
        if (*m.pairs[i] == ObjectFate::Interpolated) {
            g.rig = interpolateRig(first.groups[i].rig, second.groups[i].rig, t, path);
            g.deformed = nullptr; // to be solved for the new targets
        }
        out.groups.push_back(std::move(g));
    }
    resolveJoins(out); // parts follow their parents' interpolated poses
    return out;
}

} // namespace

int InbetweenPlan::interpolatedCount() const
{
    return int(std::count_if(objects.begin(), objects.end(), [](const InbetweenObjectReport &r) {
        return r.fate == ObjectFate::Interpolated;
    }));
}

InbetweenPlan planInbetweens(const Frame &first, const Frame &second,
                             const std::vector<double> &times, TargetPath path,
                             const DrawingFits &fits)
{
    InbetweenPlan plan;
    const Matching m = matchObjects(first, second, fits);
    plan.objects = m.report;
    plan.times = times;
    plan.frames.reserve(times.size());
    for (double t : times)
        plan.frames.push_back(
            inbetweenFrame(first, second, m, std::isfinite(t) ? t : 0.0, path, fits));
    return plan;
}

std::vector<int> differentDrawings(const Frame &first, const Frame &second)
{
    const auto inked = [](const StrokeGroup &g) {
        return std::any_of(g.strokes.begin(), g.strokes.end(), [](const Stroke &s) {
            return s.data && qAlpha(s.data->color) != 0 && s.data->points.size() >= 2;
        });
    };
    std::vector<int> out;
    const std::size_t common = std::min(first.groups.size(), second.groups.size());
    for (std::size_t i = 0; i < common; ++i) {
        const StrokeGroup &a = first.groups[i], &b = second.groups[i];
        if (!sameDrawing(a, b) && inked(a) && inked(b))
            out.push_back(int(i));
    }
    return out;
}

} // namespace finbook::model
