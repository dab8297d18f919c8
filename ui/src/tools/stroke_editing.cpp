#include "stroke_hit.h"

#include <finbook/model/commands.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/uncovered_lines.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/ui/skeleton/skeleton_follow.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QClipboard>
#include <QDataStream>
#include <QIODevice>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
constexpr quint32 kClipMagic = 0x46534b31; // "FSK1"
constexpr quint32 kClipVersion = 2;        // 1: strokes only; 2: then the fills
constexpr quint32 kMaxClipStrokes = 1'000'000;
constexpr quint32 kMaxClipFills = 1'000'000;
constexpr quint64 kMaxClipPoints = 20'000'000;

bool finite(float v)
{
    return std::isfinite(v);
}
} // namespace

QByteArray encodeStrokes(const std::vector<model::StrokeDataPtr> &strokes,
                         const std::vector<ClipboardFill> &fills)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(QDataStream::Qt_6_4);
    out.setFloatingPointPrecision(QDataStream::SinglePrecision);
    out << kClipMagic << kClipVersion << quint32(strokes.size());
    for (const model::StrokeDataPtr &s : strokes) {
        out << quint32(s->color) << s->width << quint32(s->points.size());
        for (const model::StrokePoint &p : s->points)
            out << p.x << p.y << p.pressure;
    }
    out.setFloatingPointPrecision(QDataStream::DoublePrecision);
    out << quint32(fills.size());
    for (const ClipboardFill &f : fills)
        out << quint32(f.color) << f.seed.x() << f.seed.y();
    return bytes;
}

namespace {
// Version 2's fills, after the strokes: each a colour and a finite seed point.
bool decodeFills(QDataStream &in, std::vector<ClipboardFill> &fills)
{
    in.setFloatingPointPrecision(QDataStream::DoublePrecision);
    quint32 count = 0;
    in >> count;
    // Each fill takes 20 bytes: refuse counts the remaining bytes cannot hold.
    if (in.status() != QDataStream::Ok || count > kMaxClipFills ||
        quint64(count) * 20 > quint64(in.device()->bytesAvailable()))
        return false;
    for (quint32 i = 0; i < count; ++i) {
        quint32 color = 0;
        double x = 0, y = 0;
        in >> color >> x >> y;
        if (in.status() != QDataStream::Ok || !std::isfinite(x) || !std::isfinite(y))
            return false;
        fills.push_back({color, QPointF(x, y)});
    }
    return true;
}
} // namespace

std::optional<ClipboardContent> decodeStrokes(const QByteArray &bytes)
{
    QDataStream in(bytes);
    in.setVersion(QDataStream::Qt_6_4);
    in.setFloatingPointPrecision(QDataStream::SinglePrecision);
    quint32 magic = 0, version = 0, count = 0;
    in >> magic >> version >> count;
    if (in.status() != QDataStream::Ok || magic != kClipMagic || version < 1 ||
        version > kClipVersion || count > kMaxClipStrokes)
        return std::nullopt;
    ClipboardContent content;
    std::vector<model::StrokeDataPtr> &strokes = content.strokes;
    quint64 total = 0;
    for (quint32 i = 0; i < count; ++i) {
        auto s = std::make_shared<model::StrokeData>();
        quint32 color = 0, n = 0;
        in >> color >> s->width >> n;
        total += n;
        // Each point takes 12 bytes: refuse counts the remaining bytes cannot hold.
        if (in.status() != QDataStream::Ok || n == 0 || total > kMaxClipPoints ||
            quint64(n) * 12 > quint64(bytes.size()) ||
            !(s->width > 0.0f && s->width <= model::kMaxStrokeWidth)) // as a file: also NaN
            return std::nullopt;
        s->color = color;
        s->points.resize(n);
        for (model::StrokePoint &p : s->points) {
            in >> p.x >> p.y >> p.pressure;
            if (!finite(p.x) || !finite(p.y) || !finite(p.pressure))
                return std::nullopt;
            p.pressure = std::clamp(p.pressure, 0.0f, 1.0f);
        }
        if (in.status() != QDataStream::Ok)
            return std::nullopt;
        strokes.push_back(std::move(s));
    }
    if (version >= 2 && !decodeFills(in, content.fills))
        return std::nullopt;
    return content;
}

QString StrokeEditing::targetProblem(const EditorState &state)
{
    if (!state.currentFrame())
        return tr("There is no frame to draw on. Insert a frame first.");
    const model::StrokeGroup *g = state.currentGroup();
    if (g && g->locked)
        return tr("The object \"%1\" is locked. Unlock it in the Objects panel to draw on it.")
            .arg(g->name);
    if (g && !g->visible)
        return tr("The object \"%1\" is hidden. Show it in the Objects panel to draw on it.")
            .arg(g->name);
    return {};
}

std::optional<std::vector<model::Id>>
StrokeEditing::addStrokes(EditorState &state, const std::vector<model::StrokeDataPtr> &strokes,
                          const QString &text, QString *problem)
{
    if (const QString why = targetProblem(state); !why.isEmpty()) {
        if (problem)
            *problem = why;
        return std::nullopt;
    }
    model::Document *doc = state.document();
    QUndoStack *stack = doc->undoStack();
    model::Id groupId = state.currentGroupId();
    // New strokes are drawn on the posed object as shown; as rest strokes they would be bent
    // again by the rig and land elsewhere.
    const std::vector<model::Id> following = skeletonsFollowing(state, {groupId});
    beginRestEdit(doc, text, {groupId});
    if (groupId == model::kNoId) {
        auto *add = new model::AddObjectCommand(doc, state.currentFrameId(), -1, tr("Object"));
        groupId = add->groupId();
        stack->push(add);
        state.setCurrentGroupId(groupId);
    }
    std::vector<model::Id> ids;
    for (const model::StrokeDataPtr &data : strokes) {
        auto *cmd = new model::AddStrokeCommand(doc, groupId, data);
        ids.push_back(cmd->strokeId());
        stack->push(cmd);
    }
    endRestEdit(state, following);
    return ids;
}

namespace {
bool isPosed(const model::Document *doc, model::Id id)
{
    const model::StrokeGroup *g = doc->group(id);
    return g && g->isDeformed() && g->rig.isPosed();
}
} // namespace

bool StrokeEditing::applyPoses(model::Document *doc, const std::vector<model::Id> &groupIds)
{
    bool applied = false;
    for (model::Id id : groupIds)
        if (isPosed(doc, id)) {
            doc->undoStack()->push(model::makeApplyPoseCommand(doc, id));
            applied = true;
        }
    return applied;
}

void StrokeEditing::beginRestEdit(model::Document *doc, const QString &text,
                                  const std::vector<model::Id> &groupIds)
{
    const bool posed = std::any_of(groupIds.begin(), groupIds.end(),
                                   [doc](model::Id id) { return isPosed(doc, id); });
    doc->undoStack()->beginMacro(posed ? tr("%1 (pose applied)").arg(text) : text);
    applyPoses(doc, groupIds);
}

std::vector<model::Id> StrokeEditing::beginRestEditOf(model::Document *doc, const QString &text,
                                                      const std::vector<model::Id> &ids)
{
    std::vector<model::Id> groups, before;
    for (model::Id id : ids) {
        const model::StrokeLocation at = doc->locateStroke(id);
        if (!at.isValid())
            continue;
        const model::StrokeGroup &g = doc->frameAt(at).groups[std::size_t(at.group)];
        if (std::find(groups.begin(), groups.end(), g.id) != groups.end())
            continue;
        groups.push_back(g.id);
        for (const model::Stroke &s : g.strokes)
            before.push_back(s.id);
    }
    const bool posed =
        std::any_of(groups.begin(), groups.end(), [doc](model::Id id) { return isPosed(doc, id); });
    beginRestEdit(doc, text, groups);
    if (!posed)
        return ids;
    // A line's parts follow one another in its object's strokes, each starting where the one
    // before it ends; only the part that keeps the line's id was there before the bake.
    std::sort(before.begin(), before.end());
    const auto isNew = [&](const model::Stroke &s) {
        return !std::binary_search(before.begin(), before.end(), s.id) && s.data &&
               !s.data->points.empty();
    };
    const auto joined = [](const model::Stroke &a, const model::Stroke &b) { // a, then b
        const model::StrokePoint &p = a.data->points.back(), &q = b.data->points.front();
        return p.x == q.x && p.y == q.y;
    };
    std::vector<model::Id> out;
    for (model::Id id : ids) {
        const model::StrokeLocation at = doc->locateStroke(id);
        if (!at.isValid())
            continue;
        const std::vector<model::Stroke> &strokes =
            doc->frameAt(at).groups[std::size_t(at.group)].strokes;
        const std::size_t i = std::size_t(at.stroke);
        if (!strokes[i].data || strokes[i].data->points.empty()) {
            out.push_back(id);
            continue;
        }
        std::size_t first = i, last = i;
        while (first > 0 && isNew(strokes[first - 1]) && joined(strokes[first - 1], strokes[first]))
            --first;
        while (last + 1 < strokes.size() && isNew(strokes[last + 1]) &&
               joined(strokes[last], strokes[last + 1]))
            ++last;
        for (std::size_t k = first; k <= last; ++k)
            if (std::find(out.begin(), out.end(), strokes[k].id) == out.end())
                out.push_back(strokes[k].id);
    }
    return out;
}

std::vector<model::StrokeGroup> StrokeEditing::objectsNow(const model::Document *doc,
                                                          const std::vector<model::Id> &groupIds)
{
    std::vector<model::StrokeGroup> out;
    for (model::Id id : groupIds)
        if (const model::StrokeGroup *g = doc->group(id);
            g && std::none_of(out.begin(), out.end(),
                              [id](const model::StrokeGroup &o) { return o.id == id; }))
            out.push_back(*g);
    return out;
}

void StrokeEditing::showUncoveredLines(model::Document *doc,
                                       const std::vector<model::StrokeGroup> &before)
{
    for (const model::StrokeGroup &g : before)
        model::pushUncoveredParts(doc, g.id, g);
}

void StrokeEditing::endRestEdit(EditorState &state, const std::vector<model::Id> &following)
{
    followDrawing(state, following);
    state.document()->undoStack()->endMacro();
}

bool StrokeEditing::deleteSelection(EditorState &state)
{
    const std::vector<model::Id> ids = state.selectedStrokes();
    const std::vector<model::Id> pictures = state.selectedPictures();
    if (ids.empty() && pictures.empty())
        return false;
    model::Document *doc = state.document();
    std::vector<model::Id> groups;
    for (model::Id id : ids)
        if (const model::StrokeLocation at = doc->locateStroke(id); at.isValid())
            groups.push_back(doc->frameAt(at).groups[std::size_t(at.group)].id);
    const std::vector<model::Id> following = skeletonsFollowing(state, groups);
    const QString text = ids.empty() ? tr("Delete Picture") : tr("Delete Strokes");
    const std::vector<model::Id> doomed = beginRestEditOf(doc, text, ids);
    const std::vector<model::StrokeGroup> before = objectsNow(doc, groups);
    for (model::Id id : doomed)
        doc->undoStack()->push(new model::RemoveStrokeCommand(doc, id));
    showUncoveredLines(doc, before); // a head deleted shows the arms' tops behind it
    // A picture object goes with its picture, unless lines drawn on it stay.
    for (model::Id id : pictures)
        if (const model::StrokeGroup *g = doc->group(id); g && g->picture && isEditable(*g)) {
            if (g->strokes.empty())
                doc->undoStack()->push(new model::RemoveObjectCommand(doc, id));
            else
                doc->undoStack()->push(new model::SetPictureCommand(doc, id, nullptr, text));
        }
    endRestEdit(state, following);
    state.setSelectedStrokes({});
    return true;
}

void StrokeEditing::selectAll(EditorState &state)
{
    std::vector<model::Id> ids, pictures;
    if (const model::Frame *f = state.currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            if (isEditable(g)) {
                for (const model::Stroke &s : g.strokes)
                    ids.push_back(s.id);
                if (g.picture)
                    pictures.push_back(g.id);
            }
    state.setSelection(std::move(ids), std::move(pictures));
}

std::vector<model::StrokeDataPtr> StrokeEditing::selectedData(const EditorState &state)
{
    std::vector<model::StrokeDataPtr> data;
    const std::vector<model::Id> &selected = state.selectedStrokes();
    // Drawing order, not selection order, so a paste stacks strokes as they were.
    if (const model::Frame *f = state.currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            for (const model::Stroke &s : g.strokes)
                if (std::find(selected.begin(), selected.end(), s.id) != selected.end())
                    data.push_back(s.data);
    return data;
}

std::vector<ClipboardFill> StrokeEditing::selectedFills(const EditorState &state)
{
    std::vector<ClipboardFill> fills;
    const std::vector<model::Id> &selected = state.selectedStrokes();
    const auto isSelected = [&selected](model::Id id) {
        return std::find(selected.begin(), selected.end(), id) != selected.end();
    };
    // Each region of a fill (Fill::more too) whose strokes are all selected; the paste fills
    // each as a click of the Fill tool would.
    const auto take = [&](QRgb color, QPointF seed, const std::vector<model::Id> &strokes) {
        if (!strokes.empty() && std::all_of(strokes.begin(), strokes.end(), isSelected))
            fills.push_back({color, seed});
    };
    if (const model::Frame *f = state.currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            for (const model::Fill &fill : g.fills) {
                take(fill.color, fill.seed, fill.strokes);
                for (const model::FillPlace &place : fill.more)
                    take(fill.color, place.seed, place.strokes);
            }
    return fills;
}

namespace {

// The picked pictures as they show, in drawing order, on one transparent picture the size of
// their bounds (what another program, or Finbook's own Paste, takes from the clipboard).
QImage selectedPicturesImage(const EditorState &state)
{
    const model::Frame *frame = state.currentFrame();
    const std::vector<model::Id> &picked = state.selectedPictures();
    if (!frame || picked.empty())
        return {};
    std::vector<const model::StrokeGroup *> groups;
    QRectF bounds;
    for (const model::StrokeGroup &g : frame->groups)
        if (g.picture && std::find(picked.begin(), picked.end(), g.id) != picked.end()) {
            groups.push_back(&g);
            bounds |= model::shownPictureBounds(g);
        }
    const QRect box = bounds.toAlignedRect();
    if (groups.empty() || box.isEmpty() || box.width() > model::kMaxPictureSide ||
        box.height() > model::kMaxPictureSide)
        return {};
    QImage image(box.size(), QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return {};
    image.fill(Qt::transparent);
    for (const model::StrokeGroup *g : groups)
        model::drawPicture(image, QTransform::fromTranslate(-box.left(), -box.top()), *g);
    return image;
}

} // namespace

bool StrokeEditing::copySelection(const EditorState &state)
{
    const std::vector<model::StrokeDataPtr> data = selectedData(state);
    const QImage pictures = selectedPicturesImage(state);
    if (data.empty() && pictures.isNull())
        return false;
    auto *mime = new QMimeData;
    if (!data.empty())
        mime->setData(QString::fromLatin1(kStrokesMimeType),
                      encodeStrokes(data, selectedFills(state)));
    if (!pictures.isNull())
        mime->setImageData(pictures);
    QApplication::clipboard()->setMimeData(mime);
    return true;
}

bool StrokeEditing::cutSelection(EditorState &state)
{
    if (!copySelection(state))
        return false;
    model::Document *doc = state.document();
    doc->undoStack()->beginMacro(tr("Cut"));
    deleteSelection(state);
    doc->undoStack()->endMacro();
    return true;
}

bool StrokeEditing::clipboardHasStrokes()
{
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    return mime && mime->hasFormat(QString::fromLatin1(kStrokesMimeType));
}

namespace {
QRectF bounds(const std::vector<model::StrokeDataPtr> &strokes)
{
    qreal left = 0, top = 0, right = 0, bottom = 0;
    bool first = true;
    for (const model::StrokeDataPtr &s : strokes)
        for (const model::StrokePoint &p : s->points) {
            left = first ? p.x : std::min<qreal>(left, p.x);
            right = first ? p.x : std::max<qreal>(right, p.x);
            top = first ? p.y : std::min<qreal>(top, p.y);
            bottom = first ? p.y : std::max<qreal>(bottom, p.y);
            first = false;
        }
    return QRectF(QPointF(left, top), QPointF(right, bottom));
}

model::StrokeDataPtr shifted(const model::StrokeData &data, QPointF by)
{
    auto moved = std::make_shared<model::StrokeData>(data);
    for (model::StrokePoint &p : moved->points) {
        p.x += float(by.x());
        p.y += float(by.y());
    }
    return moved;
}

bool frameHas(const model::Frame &frame, const model::StrokeData &data)
{
    for (const model::StrokeGroup &g : frame.groups)
        for (const model::Stroke &s : g.strokes)
            if (s.data->points == data.points)
                return true;
    return false;
}
} // namespace

QPointF StrokeEditing::pasteShift(const model::Frame *frame,
                                  const std::vector<model::StrokeDataPtr> &strokes,
                                  std::optional<QPointF> at)
{
    if (strokes.empty())
        return {};
    if (at && std::isfinite(at->x()) && std::isfinite(at->y()))
        return *at - bounds(strokes).center();
    // In place when the original is not in this frame (pasting into another frame keeps the
    // drawing in register); else one step past the original and the copies already pasted
    // (the first stroke tells where each one is).
    constexpr int kMaxSteps = 100;
    for (int step = 0; frame && step < kMaxSteps; ++step) {
        const QPointF by(kPasteStep * step, kPasteStep * step);
        if (!frameHas(*frame, *shifted(*strokes.front(), by)))
            return by;
    }
    return {kPasteStep, kPasteStep};
}

bool StrokeEditing::paste(EditorState &state, QString *problem, std::optional<QPointF> at)
{
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    if (!mime || !mime->hasFormat(QString::fromLatin1(kStrokesMimeType)))
        return false;
    const auto clip = decodeStrokes(mime->data(QString::fromLatin1(kStrokesMimeType)));
    if (!clip || clip->strokes.empty()) {
        if (problem)
            *problem = tr("The clipboard holds strokes this version of Finbook cannot read.");
        return false;
    }
    const QPointF by = pasteShift(state.currentFrame(), clip->strokes, at);
    std::vector<model::StrokeDataPtr> placed;
    for (const model::StrokeDataPtr &data : clip->strokes)
        placed.push_back(shifted(*data, by));
    model::Document *doc = state.document();
    const bool withFills = !clip->fills.empty() && targetProblem(state).isEmpty();
    if (withFills) // the strokes and their fills: one undo step
        doc->undoStack()->beginMacro(tr("Paste"));
    const auto ids = addStrokes(state, placed, tr("Paste"), problem);
    // The pasted strokes make the copied regions again (addStrokes left the object at rest,
    // as the seeds are); a region the target's own strokes cut differently gets what lies at
    // the seed, as a click of the Fill tool there would.
    for (const ClipboardFill &fill : ids ? clip->fills : std::vector<ClipboardFill>{})
        if (auto command =
                model::fillRegionCommand(doc, state.currentGroupId(), fill.seed + by, fill.color))
            doc->undoStack()->push(command.release());
    if (withFills)
        doc->undoStack()->endMacro();
    if (!ids)
        return false;
    state.setSelectedStrokes(*ids);
    return true;
}

} // namespace finbook::ui
