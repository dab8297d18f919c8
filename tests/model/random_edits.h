// Random edits through real commands, for undo/redo property tests.
#pragma once

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/commands.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>

#include <QRandomGenerator>

#include <memory>

namespace finbook::testing {

inline model::StrokeDataPtr randomStrokeData(QRandomGenerator &rng)
{
    auto data = std::make_shared<model::StrokeData>();
    const int n = 1 + int(rng.bounded(12));
    float x = float(rng.bounded(1000.0)), y = float(rng.bounded(700.0));
    for (int i = 0; i < n; ++i) {
        x += float(rng.bounded(20.0) - 10.0);
        y += float(rng.bounded(20.0) - 10.0);
        data->points.push_back({x, y, float(rng.bounded(65536)) / 65535.0f});
    }
    data->color = 0xff000000u | rng.bounded(0x1000000u);
    data->width = 1.0f + float(rng.bounded(8));
    return data;
}

// A small random skeleton (a random tree, root 0) without the automatic builder: fast, and
// every shape of tree the hand edits must keep valid.
inline model::SkeletonRig randomSkeleton(QRandomGenerator &rng)
{
    model::SkeletonRig s;
    const int n = 2 + int(rng.bounded(6));
    for (int j = 0; j < n; ++j) {
        s.joints.emplace_back(rng.bounded(1000.0), rng.bounded(700.0));
        s.parent.push_back(j == 0 ? -1 : int(rng.bounded(j)));
        s.radius.push_back(rng.bounded(20.0));
    }
    s.root = 0;
    s.settings.complexity = rng.bounded(1.0);
    return s.atRest();
}

// One random skeleton edit of object `groupId` (its skeleton, if it has one): build, pose,
// lock, reset a bone or everything, move, insert or delete a joint, change skinning, join
// it to another object of its frame, detach it, make it its character's root.
inline std::unique_ptr<QUndoCommand> randomSkeletonCommand(model::Document &doc, model::Id groupId,
                                                           QRandomGenerator &rng)
{
    using namespace model;
    const StrokeGroup *g = doc.group(groupId);
    const int n = g ? g->rig.skeleton.jointCount() : 0;
    const int joint = int(rng.bounded(std::max(n, 1)));
    const QPointF somewhere(rng.bounded(1000.0), rng.bounded(700.0));
    // Another object of the same frame, for joins.
    Id other = kNoId, frameId = kNoId;
    if (const GroupLocation at = doc.locateGroup(groupId); at.isValid()) {
        const Frame &f = doc.frameAt(at);
        other = f.groups[rng.bounded(quint32(f.groups.size()))].id;
        frameId = f.id;
    }
    switch (n == 0 ? 0 : rng.bounded(13)) {
    case 0:
        return std::make_unique<BuildSkeletonCommand>(&doc, groupId, randomSkeleton(rng));
    case 1:
    case 2: {
        std::vector<double> angles(std::size_t(n), 0.0);
        for (double &a : angles)
            a = rng.bounded(2) ? rng.bounded(6.0) - 3.0 : 0.0;
        const QPointF offset = rng.bounded(2) ? QPointF(rng.bounded(40.0), 0.0) : QPointF();
        return std::make_unique<PoseBonesCommand>(&doc, groupId, angles, offset,
                                                  int(rng.bounded(3)));
    }
    case 3:
        return std::make_unique<SetJointLockCommand>(&doc, groupId, joint, rng.bounded(3) != 0);
    case 4:
        if (rng.bounded(2))
            return std::make_unique<ResetPoseCommand>(&doc, groupId);
        return std::make_unique<ResetBonePoseCommand>(&doc, groupId, joint);
    case 5:
        return std::make_unique<MoveJointCommand>(&doc, groupId, joint, somewhere,
                                                  int(rng.bounded(3)));
    case 6:
        return std::make_unique<InsertJointCommand>(&doc, groupId, joint, somewhere);
    case 7:
        return std::make_unique<DeleteJointCommand>(&doc, groupId, joint);
    case 9: // may be a loop or a part without a skeleton: then obsolete
        return std::make_unique<JoinPartCommand>(&doc, groupId,
                                                 joinAt(g->rig.skeleton, other, somewhere));
    case 10:
        return std::make_unique<DetachPartCommand>(&doc, groupId);
    case 11:
        return std::make_unique<MakeCharacterRootCommand>(&doc, groupId);
    case 12:
        return std::make_unique<JoinOverlappingPartsCommand>(&doc, frameId);
    default:
        return std::make_unique<SetSkinningModeCommand>(
            &doc, groupId, SkinningMode(rng.bounded(kLastSkinningMode + 1)));
    }
}

// Picks a random id of a live entity (0 when there is none).
struct Picks {
    model::Id frame = model::kNoId;
    model::Id group = model::kNoId;
    model::Id stroke = model::kNoId;
    model::Id pin = model::kNoId;
};

inline Picks randomPicks(const model::Document &doc, QRandomGenerator &rng)
{
    Picks p;
    if (doc.frameCount() == 0)
        return p;
    const model::Frame &f = doc.frameAt(int(rng.bounded(doc.frameCount())));
    p.frame = f.id;
    if (f.groups.empty())
        return p;
    const model::StrokeGroup &g = f.groups[rng.bounded(quint32(f.groups.size()))];
    p.group = g.id;
    if (!g.strokes.empty())
        p.stroke = g.strokes[rng.bounded(quint32(g.strokes.size()))].id;
    if (!g.rig.pins.empty())
        p.pin = g.rig.pins[rng.bounded(quint32(g.rig.pins.size()))].id;
    return p;
}

// A fill edit on object `groupId`: Fill All when the object has unfilled regions, else a fill
// added (random seed, colour and strokes of the object) or one taken away.
inline std::unique_ptr<QUndoCommand> randomFillCommand(model::Document &doc, model::Id groupId,
                                                       QRandomGenerator &rng)
{
    using namespace model;
    const QRgb color = 0xff000000u | rng.bounded(0x1000000u);
    if (rng.bounded(2))
        if (auto all = fillAllRegionsCommand(&doc, groupId, color))
            return all;
    const StrokeGroup *g = doc.group(groupId);
    std::vector<Fill> fills = g ? g->fills : std::vector<Fill>{};
    if (!fills.empty() && rng.bounded(3) == 0) {
        fills.erase(fills.begin() + rng.bounded(quint32(fills.size())));
    } else {
        Fill f{color, QPointF(rng.bounded(1000.0), rng.bounded(700.0)), {}, {}, {}};
        if (g)
            for (const Stroke &s : g->strokes)
                if (rng.bounded(2))
                    f.strokes.push_back(s.id);
        std::sort(f.strokes.begin(), f.strokes.end());
        fills.push_back(f);
    }
    return std::make_unique<SetFillsCommand>(&doc, groupId, std::move(fills),
                                             QStringLiteral("Fill"));
}

// A camera edit: a key added or changed (any easing), removed or moved (never null).
inline std::unique_ptr<QUndoCommand> randomCameraCommand(model::Document &doc,
                                                         QRandomGenerator &rng)
{
    using namespace model;
    const std::vector<CameraKey> &keys = doc.camera().keys;
    if (!keys.empty() && rng.bounded(3) == 0) {
        const qint64 tick = keys[rng.bounded(quint32(keys.size()))].tick;
        if (auto c = rng.bounded(2) ? removeCameraKeyCommand(&doc, tick)
                                    : moveCameraKeyCommand(&doc, tick, rng.bounded(40)))
            return c;
    }
    CameraKey k;
    k.tick = rng.bounded(40);
    k.center = QPointF(rng.bounded(2000.0) - 500.0, rng.bounded(2000.0) - 500.0);
    k.zoom = 0.25 + rng.bounded(4.0);
    k.rotation = rng.bounded(720.0) - 360.0;
    k.easing = CameraEasing(rng.bounded(kCameraEasingCount));
    k.control1 = QPointF(rng.bounded(1.0), rng.bounded(1.0));
    k.control2 = QPointF(rng.bounded(1.0), rng.bounded(1.0));
    if (auto c = setCameraKeyCommand(&doc, k, rng.bounded(2) ? -1 : 1))
        return c;
    return std::make_unique<SetCameraCommand>(&doc, doc.camera(), QStringLiteral("Camera"));
}

// A layer edit: add, duplicate, remove, reorder, new properties, time inserted or deleted,
// cels moved, copied, pasted or removed.
inline std::unique_ptr<QUndoCommand> randomLayerCommand(model::Document &doc, QRandomGenerator &rng)
{
    using namespace model;
    const Id layer = doc.layerAt(int(rng.bounded(doc.layerCount()))).id;
    const qint64 tick = rng.bounded(12);
    // A few cels of the layer (and now and then of the next one too), for dope sheet edits.
    std::vector<Id> cels;
    for (int l = doc.layerIndex(layer); l < doc.layerCount() && l <= doc.layerIndex(layer) + 1; ++l)
        for (const Frame &f : doc.layerAt(l).cels)
            if (rng.bounded(3) == 0 && (l == doc.layerIndex(layer) || rng.bounded(2) == 0))
                cels.push_back(f.id);
    switch (rng.bounded(10)) {
    case 7:
        if (auto c = rearrangeCelsCommand(&doc, cels, int(rng.bounded(3)) - 1,
                                          qint64(rng.bounded(13)) - 6, rng.bounded(3) == 0))
            return c;
        break;
    case 8: {
        std::vector<std::vector<Frame>> rows(1 + rng.bounded(2));
        for (Id id : cels)
            rows[rng.bounded(int(rows.size()))].push_back(*doc.frame(id));
        if (auto c = pasteCelsCommand(&doc, rows, layer, tick))
            return c;
        break;
    }
    case 9:
        if (auto c = removeCelsCommand(&doc, cels))
            return c;
        break;
    case 0:
        return std::make_unique<AddLayerCommand>(&doc, int(rng.bounded(doc.layerCount() + 1)),
                                                 QStringLiteral("L%1").arg(rng.bounded(100)));
    case 1:
        return std::make_unique<DuplicateLayerCommand>(&doc, layer);
    case 2:
        return std::make_unique<RemoveLayerCommand>(&doc, layer);
    case 3:
        return std::make_unique<MoveLayerCommand>(&doc, layer, int(rng.bounded(doc.layerCount())));
    case 4: {
        LayerProperties p = doc.layer(layer)->properties;
        p.visible = rng.bounded(4) != 0;
        p.locked = rng.bounded(4) == 0;
        p.onionSkin = rng.bounded(2) == 0;
        p.opacity = rng.bounded(1.0);
        p.depth = rng.bounded(3.0) - 0.5;
        p.name = QStringLiteral("n%1").arg(rng.bounded(100));
        return std::make_unique<SetLayerPropertiesCommand>(&doc, layer, p, QStringLiteral("P"),
                                                           int(rng.bounded(2)) - 1);
    }
    case 5:
        if (auto c = insertTimeCommand(&doc, {layer}, tick, 1 + int(rng.bounded(3))))
            return c;
        break;
    default:
        if (auto c = deleteTimeCommand(&doc, {layer}, tick, 1 + int(rng.bounded(4))))
            return c;
        break;
    }
    return std::make_unique<AddLayerCommand>(&doc, 0, QStringLiteral("back"));
}

// Builds one random command against the document's current state (never null). Now and then
// another layer becomes current first (editing state, not undone: undo must not depend on it).
inline std::unique_ptr<QUndoCommand> randomCommand(model::Document &doc, QRandomGenerator &rng)
{
    using namespace model;
    if (rng.bounded(8) == 0)
        doc.setCurrentLayer(doc.layerAt(int(rng.bounded(doc.layerCount()))).id);
    const Picks p = randomPicks(doc, rng);
    const int n = doc.frameCount();
    const QPointF somewhere(rng.bounded(1000.0), rng.bounded(700.0));
    switch (rng.bounded(27)) {
    case 25:
    case 26:
        return randomLayerCommand(doc, rng);
    case 24:
        return randomCameraCommand(doc, rng);
    case 22:
        return randomFillCommand(doc, p.group, rng);
    case 23:
        if (auto gap = setCloseGapCommand(&doc, rng.bounded(3) ? rng.bounded(40.0) : -1.0))
            return gap;
        return randomFillCommand(doc, p.group, rng);
    case 19:
    case 20:
    case 21:
        return randomSkeletonCommand(doc, p.group, rng);
    case 14:
    case 15:
        return std::make_unique<AddPinCommand>(&doc, p.group, somewhere,
                                               somewhere + QPointF(rng.bounded(9.0), 0.0));
    case 16:
        return std::make_unique<RemovePinCommand>(&doc, p.group, p.pin);
    case 17:
        return std::make_unique<MovePinCommand>(&doc, p.group, p.pin, somewhere,
                                                int(rng.bounded(3)));
    case 18:
        if (rng.bounded(2))
            return std::make_unique<ResetPoseCommand>(&doc, p.group);
        return std::make_unique<SetMeshDensityCommand>(&doc, p.group, rng.bounded(4.0),
                                                       int(rng.bounded(3)));
    case 0:
    case 1:
        return std::make_unique<AddStrokeCommand>(&doc, p.group, randomStrokeData(rng),
                                                  int(rng.bounded(4)) - 1);
    case 2:
        return std::make_unique<RemoveStrokeCommand>(&doc, p.stroke);
    case 3:
        return std::make_unique<AddObjectCommand>(&doc, p.frame, int(rng.bounded(4)) - 1,
                                                  QStringLiteral("obj%1").arg(rng.bounded(100)));
    case 4:
        return std::make_unique<RemoveObjectCommand>(&doc, p.group);
    case 5:
        return std::make_unique<RenameObjectCommand>(&doc, p.group,
                                                     QStringLiteral("n%1").arg(rng.bounded(100)));
    case 6:
        return std::make_unique<ReorderObjectCommand>(&doc, p.group, int(rng.bounded(4)));
    case 7: {
        const Picks q = randomPicks(doc, rng);
        return std::make_unique<MoveStrokesCommand>(&doc, std::vector<Id>{p.stroke, q.stroke},
                                                    q.group);
    }
    case 8:
        return std::make_unique<InsertFrameCommand>(&doc, int(rng.bounded(n + 1)));
    case 9:
        return std::make_unique<DuplicateFrameCommand>(&doc, p.frame, int(rng.bounded(n + 1)));
    case 10:
        return std::make_unique<DeleteFrameCommand>(&doc, p.frame);
    case 11:
        return std::make_unique<MoveFrameCommand>(&doc, int(rng.bounded(std::max(n, 1))),
                                                  int(rng.bounded(std::max(n, 1))));
    case 12: {
        DocumentSettings s = doc.settings();
        s.fps = 1 + int(rng.bounded(60));
        s.loop = rng.bounded(2) == 0;
        s.canvasSize = QSize(100 + int(rng.bounded(2000)), 100 + int(rng.bounded(2000)));
        s.playStart = int(rng.bounded(4));
        s.playEnd = int(rng.bounded(6)) - 1;
        return std::make_unique<ChangeSettingsCommand>(&doc, s);
    }
    default:
        if (rng.bounded(2))
            return std::make_unique<SetFrameHoldCommand>(&doc, p.frame, 1 + int(rng.bounded(4)));
        if (p.stroke != kNoId)
            return std::make_unique<ReplaceStrokeDataCommand>(
                &doc, std::vector<Id>{p.stroke}, std::vector<StrokeDataPtr>{randomStrokeData(rng)},
                QStringLiteral("Transform"));
        return std::make_unique<SetObjectFlagCommand>(
            &doc, p.group, rng.bounded(2) ? ObjectFlag::Visible : ObjectFlag::Locked,
            rng.bounded(2) == 0);
    }
}

} // namespace finbook::testing
