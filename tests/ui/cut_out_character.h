// A character for the tools' tests on a cut-out pose: a body and two arms 190 px long, each
// region filled in a colour of its own, its automatic skeleton in cut-out skinning with the
// arms turned 40° at the shoulders and bent at the elbows; and where its left elbow is shown,
// with a line across the arm there (square to the arm's two bones), `half` px each side.
#pragma once

#include "../model/bake_support.h"
#include "../model/fill_support.h"

#include <finbook/model/fill/fill_commands.h>

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace finbook::test {

struct CutOutArm {
    QPointF elbow;
    QLineF across;
};

inline std::optional<CutOutArm> poseCutOutCharacter(model::Document &doc, model::Id g,
                                                    double half = 30.0)
{
    using namespace finbook::testing;
    QUndoStack *stack = doc.undoStack();
    const auto ring = [](QPointF c, double rx, double ry) {
        QPolygonF out;
        for (int i = 0; i <= 48; ++i)
            out << c + QPointF(rx * std::cos(i * M_PI / 24), ry * std::sin(i * M_PI / 24));
        return out;
    };
    const auto arm = [](QPointF root, double angle) {
        const QPointF d(std::cos(angle), std::sin(angle)), n(-d.y(), d.x());
        const QPointF a = root + n * 14, b = root - n * 14;
        return QPolygonF{a, a + d * 190, b + d * 190, b, a};
    };
    stack->push(
        new model::AddStrokeCommand(&doc, g, polylineStroke(ring({300, 300}, 70, 110), 4.0, 3.0f)));
    stack->push(new model::AddStrokeCommand(
        &doc, g, polylineStroke(arm({260, 230}, M_PI * 0.85), 4.0, 3.0f)));
    stack->push(new model::AddStrokeCommand(
        &doc, g, polylineStroke(arm({340, 230}, M_PI * 0.15), 4.0, 3.0f)));
    if (auto all = model::fillAllRegionsCommand(&doc, g, 0xff808080))
        stack->push(all.release());
    std::vector<model::Fill> fills = doc.group(g)->fills;
    for (std::size_t i = 0; i < fills.size(); ++i)
        fills[i].color = distinctColour(i);
    stack->push(new model::SetFillsCommand(&doc, g, fills, QStringLiteral("Colours")));
    model::Rig rig =
        skeletonBend(*doc.group(g), doc.settings().closeGap, model::SkinningMode::CutOut, 40.0);
    if (rig.empty())
        return std::nullopt;
    bendElbows(rig, -0.4);
    if (!poseObject(doc, g, rig).isEmpty())
        return std::nullopt;
    stack->clear();
    // The left elbow: the leftmost.
    const std::vector<ElbowRub> elbows = elbowRubs(doc.group(g)->rig.skeleton, half);
    const auto left =
        std::min_element(elbows.begin(), elbows.end(),
                         [](const ElbowRub &a, const ElbowRub &b) { return a.at.x() < b.at.x(); });
    if (left == elbows.end())
        return std::nullopt;
    return CutOutArm{left->at, left->across};
}

// Inked strokes of object g that lie along another (more than five points within a pixel of
// it): a line drawn twice.
inline int doubledLines(const model::StrokeGroup &g)
{
    int doubled = 0;
    for (std::size_t a = 0; a < g.strokes.size(); ++a)
        for (std::size_t b = a + 1; b < g.strokes.size(); ++b) {
            if (qAlpha(g.strokes[a].data->color) == 0 || qAlpha(g.strokes[b].data->color) == 0)
                continue;
            int near = 0;
            for (const model::StrokePoint &p : g.strokes[a].data->points)
                for (const model::StrokePoint &q : g.strokes[b].data->points)
                    if (std::hypot(p.x - q.x, p.y - q.y) < 1.0) {
                        ++near;
                        break;
                    }
            doubled += near > 5;
        }
    return doubled;
}

} // namespace finbook::test
