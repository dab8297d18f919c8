#include <finbook/model/document.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/layers/cel_editing.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QClipboard>
#include <QMimeData>

#include <algorithm>

namespace finbook::ui {

namespace {
// What was copied last in this process, and the token the system clipboard holds for it.
struct CopiedCels {
    QByteArray token;
    std::vector<std::vector<model::Frame>> rows;
};

CopiedCels &copied()
{
    static CopiedCels cels;
    return cels;
}

QByteArray newToken()
{
    static quint64 counter = 0;
    return QByteArray::number(QCoreApplication::applicationPid()) + ':' +
           QByteArray::number(++counter);
}

void push(model::Document *doc, std::unique_ptr<QUndoCommand> command)
{
    doc->undoStack()->push(command.release());
}

// The layers the picked cels are on, the first tick they start at and the ticks they span
// (to the end of the last); nullopt when none is picked.
struct PickedSpan {
    std::vector<model::Id> layers;
    qint64 first = 0, ticks = 0;
};

std::optional<PickedSpan> pickedSpan(const EditorState &state)
{
    const model::Document *doc = state.document();
    PickedSpan span;
    qint64 last = -1;
    span.first = std::numeric_limits<qint64>::max();
    const auto &ids = state.selectedCels();
    for (const model::Layer &layer : doc->layers()) {
        bool picked = false;
        qint64 start = 0;
        for (const model::Frame &cel : layer.cels) {
            const qint64 end = start + std::clamp(cel.hold, 1, model::kMaxHold);
            if (std::find(ids.begin(), ids.end(), cel.id) != ids.end()) {
                picked = true;
                span.first = std::min(span.first, start);
                last = std::max(last, end);
            }
            start = end;
        }
        if (picked)
            span.layers.push_back(layer.id);
    }
    if (span.layers.empty())
        return std::nullopt;
    span.ticks = last - span.first;
    return span;
}
} // namespace

std::vector<std::vector<model::Frame>> CelEditing::pickedRows(const EditorState &state)
{
    std::vector<std::vector<model::Frame>> rows;
    const auto &ids = state.selectedCels();
    for (const model::Layer &layer : state.document()->layers()) {
        std::vector<model::Frame> row;
        for (const model::Frame &cel : layer.cels)
            if (std::find(ids.begin(), ids.end(), cel.id) != ids.end())
                row.push_back(cel);
        if (!row.empty() || !rows.empty()) // rows keep their distance; none before the first
            rows.push_back(std::move(row));
    }
    while (!rows.empty() && rows.back().empty())
        rows.pop_back();
    return rows;
}

bool CelEditing::copy(const EditorState &state)
{
    std::vector<std::vector<model::Frame>> rows = pickedRows(state);
    if (rows.empty())
        return false;
    copied() = {newToken(), std::move(rows)};
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(kCelsMimeType), copied().token);
    QApplication::clipboard()->setMimeData(mime);
    return true;
}

bool CelEditing::cut(EditorState &state)
{
    if (!copy(state))
        return false;
    model::Document *doc = state.document();
    auto command = model::removeCelsCommand(doc, state.selectedCels());
    if (!command)
        return false;
    command->setText(tr("Cut Cels"));
    push(doc, std::move(command));
    state.setSelectedCels({});
    return true;
}

bool CelEditing::remove(EditorState &state)
{
    model::Document *doc = state.document();
    auto command = model::removeCelsCommand(doc, state.selectedCels());
    if (!command)
        return false;
    push(doc, std::move(command));
    state.setSelectedCels({});
    return true;
}

bool CelEditing::clipboardHasCels()
{
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    return mime && !copied().token.isEmpty() &&
           mime->data(QString::fromLatin1(kCelsMimeType)) == copied().token;
}

bool CelEditing::paste(EditorState &state, QString *problem)
{
    if (!clipboardHasCels()) {
        if (problem)
            *problem = tr("No cels have been copied.");
        return false;
    }
    model::Document *doc = state.document();
    auto command =
        model::pasteCelsCommand(doc, copied().rows, doc->currentLayerId(), state.currentTick());
    if (!command) {
        if (problem)
            *problem = tr("The cels cannot go onto a locked layer.");
        return false;
    }
    push(doc, std::move(command));
    return true;
}

namespace {
// Insert or Delete Time (`edit`): on the picked cels' layers over the ticks they span, else one
// tick at the playhead on the current layer.
using TimeEdit = std::unique_ptr<QUndoCommand> (*)(model::Document *,
                                                   const std::vector<model::Id> &, qint64, int);
bool editTime(EditorState &state, TimeEdit edit)
{
    model::Document *doc = state.document();
    const std::optional<PickedSpan> span = pickedSpan(state);
    auto command = span ? edit(doc, span->layers, span->first,
                               int(std::min<qint64>(span->ticks, model::kMaxHold)))
                        : edit(doc, {doc->currentLayerId()}, state.currentTick(), 1);
    if (!command)
        return false;
    push(doc, std::move(command));
    return true;
}
} // namespace

bool CelEditing::insertTime(EditorState &state)
{
    return editTime(state, &model::insertTimeCommand);
}

bool CelEditing::deleteTime(EditorState &state)
{
    if (!editTime(state, &model::deleteTimeCommand))
        return false;
    state.setSelectedCels({}); // cels wholly inside the stretch are gone
    return true;
}

} // namespace finbook::ui
