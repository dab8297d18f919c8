#include <finbook/model/commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>
#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/window/editor_state.h>

#include <QAction>
#include <QInputDialog>
#include <QMenu>

#include <algorithm>

namespace finbook::ui {

SwapActions::SwapActions(EditorState *state, QWidget *dialogParent, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_dialogParent(dialogParent)
    , m_drawings(new QMenu)
{
    m_drawings->setTitle(tr("Show Dr&awing"));
    m_drawings->menuAction()->setObjectName(QStringLiteral("swap.showDrawing"));
    connect(makeAction(QStringLiteral("swap.makeSwappable"), tr("Make S&wappable"), {}),
            &QAction::triggered, this, &SwapActions::makeSwappable);
    connect(makeAction(QStringLiteral("swap.mouthChart"), tr("New Mout&h Chart"), {}),
            &QAction::triggered, this, &SwapActions::addMouthChart);
    m_menu.append(m_drawings->menuAction());
    connect(makeAction(QStringLiteral("swap.previous"), tr("&Previous Drawing"),
                       QKeySequence(Qt::Key_BracketLeft)),
            &QAction::triggered, this, [this] { step(-1); });
    connect(makeAction(QStringLiteral("swap.next"), tr("Ne&xt Drawing"),
                       QKeySequence(Qt::Key_BracketRight)),
            &QAction::triggered, this, [this] { step(+1); });
    connect(makeAction(QStringLiteral("swap.newDrawing"), tr("New Drawing in S&et"), {}),
            &QAction::triggered, this, [this] { addDrawing(false); });
    connect(
        makeAction(QStringLiteral("swap.duplicateDrawing"), tr("D&uplicate Drawing in Set"), {}),
        &QAction::triggered, this, [this] { addDrawing(true); });
    connect(makeAction(QStringLiteral("swap.renameDrawing"), tr("&Rename Drawing..."), {}),
            &QAction::triggered, this, &SwapActions::renameDrawing);
    connect(makeAction(QStringLiteral("swap.deleteDrawing"), tr("Remove Drawing from Se&t"), {}),
            &QAction::triggered, this, &SwapActions::deleteDrawing);
    connect(makeAction(QStringLiteral("swap.makeOwn"), tr("Make Drawing &Independent"), {}),
            &QAction::triggered, this, &SwapActions::makeOwn);
    action(QStringLiteral("swap.makeSwappable"))
        ->setToolTip(tr("Make the object's drawing the first of a set it swaps between, frame by "
                        "frame (mouths, hands, blinks)"));
    action(QStringLiteral("swap.mouthChart"))
        ->setToolTip(tr("A new object showing the nine mouth shapes lip sync uses"));
    action(QStringLiteral("swap.makeOwn"))
        ->setToolTip(tr("This frame keeps its drawing as its own: edits of it no longer reach "
                        "the other frames"));
    connect(m_drawings, &QMenu::aboutToShow, this,
            [this] { fillDrawingMenu(m_drawings, stepTarget()); });

    model::Document *doc = m_state->document();
    for (auto signal : {&model::Document::groupsChanged, &model::Document::frameChanged})
        connect(doc, signal, this, &SwapActions::updateEnabled);
    connect(doc, &model::Document::swapSetsChanged, this, &SwapActions::updateEnabled);
    connect(doc, &model::Document::documentReset, this, &SwapActions::updateEnabled);
    connect(m_state, &EditorState::currentFrameChanged, this, &SwapActions::updateEnabled);
    connect(m_state, &EditorState::currentGroupChanged, this, &SwapActions::updateEnabled);
    updateEnabled();
}

SwapActions::~SwapActions()
{
    delete m_drawings;
}

QAction *SwapActions::makeAction(const QString &name, const QString &text,
                                 const QKeySequence &shortcut)
{
    auto *a = new QAction(text, this);
    a->setObjectName(name);
    if (!shortcut.isEmpty())
        a->setShortcut(shortcut);
    m_menu.append(a);
    return a;
}

QAction *SwapActions::action(const QString &objectName) const
{
    for (QAction *a : m_menu)
        if (a->objectName() == objectName)
            return a;
    return nullptr;
}

const model::SwapSet *SwapActions::currentSet() const
{
    const model::StrokeGroup *g = m_state->currentGroup();
    return g ? m_state->document()->swapSet(g->swap.set) : nullptr;
}

void SwapActions::updateEnabled()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    const model::SwapSet *set = currentSet();
    const bool editable = g && !g->locked;
    action(QStringLiteral("swap.makeSwappable"))->setEnabled(editable && !set);
    action(QStringLiteral("swap.mouthChart"))->setEnabled(m_state->currentFrame() != nullptr);
    m_drawings->menuAction()->setEnabled(stepTarget() != model::kNoId);
    for (const char *name :
         {"swap.newDrawing", "swap.duplicateDrawing", "swap.renameDrawing", "swap.makeOwn"})
        action(QString::fromLatin1(name))->setEnabled(editable && set);
    const bool several = set && set->drawings.size() > 1;
    action(QStringLiteral("swap.deleteDrawing"))->setEnabled(editable && several);
    const model::StrokeGroup *target = m_state->document()->group(stepTarget());
    const model::SwapSet *targetSet =
        target ? m_state->document()->swapSet(target->swap.set) : nullptr;
    const bool steps = targetSet && targetSet->drawings.size() > 1;
    action(QStringLiteral("swap.previous"))->setEnabled(steps);
    action(QStringLiteral("swap.next"))->setEnabled(steps);
}

void SwapActions::fillDrawingMenu(QMenu *menu, model::Id groupId) const
{
    menu->clear();
    model::Document *doc = m_state->document();
    const model::StrokeGroup *g = doc->group(groupId);
    const model::SwapSet *set = g ? doc->swapSet(g->swap.set) : nullptr;
    if (!set) {
        menu->addAction(tr("(not swappable)"))->setEnabled(false);
        return;
    }
    for (const model::SwapDrawing &d : set->drawings) {
        QAction *pick = menu->addAction(d.name.isEmpty() ? tr("(unnamed)") : d.name);
        pick->setCheckable(true);
        pick->setChecked(d.id == g->swap.drawing);
        pick->setEnabled(!g->locked);
        const model::SwapLink link{set->id, d.id};
        connect(pick, &QAction::triggered, this, [this, groupId, link] { show(groupId, link); });
    }
}

void SwapActions::show(model::Id groupId, model::SwapLink drawing) const
{
    model::Document *doc = m_state->document();
    auto *command = new model::SetSwapDrawingCommand(doc, groupId, drawing);
    doc->undoStack()->push(command);
}

QString SwapActions::freshDrawingName(const model::SwapSet &set) const
{
    for (int n = int(set.drawings.size()) + 1;; ++n) {
        const QString name = QString::number(n);
        if (std::none_of(set.drawings.begin(), set.drawings.end(),
                         [&](const model::SwapDrawing &d) { return d.name == name; }))
            return name;
    }
}

void SwapActions::makeSwappable()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (!g || g->swap.linked())
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::NewSwapSetCommand(doc, g->id, g->name, QStringLiteral("1")));
    emit message(tr("\"%1\" is swappable: add drawings with Object > New Drawing in Set, and pick "
                    "one per frame with [ and ]")
                     .arg(g->name));
}

void SwapActions::addMouthChart()
{
    model::Document *doc = m_state->document();
    if (!m_state->currentFrame())
        return;
    const QSize canvas = doc->settings().canvasSize;
    QPointF centre =
        m_chartCentre ? m_chartCentre() : QPointF(canvas.width() / 2.0, canvas.height() / 2.0);
    double width = std::clamp(canvas.width() / 24.0, 24.0, 200.0);
    // Made with the head current, the mouth goes on its face: a third of its width, two thirds
    // of the way down (each drawing of a set is moved on its own afterwards).
    if (const model::StrokeGroup *face = m_state->currentGroup(); face && !face->swap.linked()) {
        QRectF box;
        for (const model::Stroke &stroke : face->strokes)
            for (const model::StrokePoint &p : stroke.data->points)
                box |= QRectF(double(p.x), double(p.y), 0.001, 0.001);
        if (box.width() > 12 && box.height() > 12) {
            centre = QPointF(box.center().x(), box.top() + box.height() * 0.68);
            width = std::clamp(box.width() / 3.0, 12.0, 200.0);
        }
    }
    // Its own layer above the current one, exposed for the whole shot: the mouth's row, which
    // lip sync cuts into the mouths as they are heard without touching the character's cels.
    doc->undoStack()->beginMacro(tr("New Mouth Chart"));
    auto *layer = new model::AddLayerCommand(doc, doc->currentLayerIndex() + 1, tr("Mouth"));
    doc->undoStack()->push(layer);
    const model::Layer *added = doc->layer(layer->layerId());
    const model::Id mouth = added ? added->cels.front().groups.front().id : model::kNoId;
    doc->undoStack()->push(new model::RenameObjectCommand(doc, mouth, tr("Mouth")));
    model::SwapSet chart =
        model::mouthChart(*doc, centre, width, 0xff202020, float(std::max(2.0, width / 40.0)));
    doc->undoStack()->push(new model::NewSwapSetCommand(doc, mouth, std::move(chart), 8));
    doc->undoStack()->endMacro();
    m_state->setCurrentGroupId(mouth); // its layer becomes current
    emit message(tr("A mouth chart on its own layer: nine mouth shapes to redraw in your style; "
                    "[ and ] swap them, Deform > Lip Sync keys them from the soundtrack"));
}

void SwapActions::addDrawing(bool copy)
{
    const model::SwapSet *set = currentSet();
    if (!set)
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(
        new model::AddSwapDrawingCommand(doc, m_state->currentGroupId(), freshDrawingName(*set),
                                         copy ? model::AddSwapDrawingCommand::Content::Copy
                                              : model::AddSwapDrawingCommand::Content::Empty));
}

void SwapActions::renameDrawing()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    const model::SwapDrawing *d = g ? m_state->document()->swapDrawing(g->swap) : nullptr;
    if (!d)
        return;
    const model::SwapLink link = g->swap;
    bool ok = false;
    const QString name =
        QInputDialog::getText(m_dialogParent, tr("Rename Drawing"), tr("Name of the drawing:"),
                              QLineEdit::Normal, d->name, &ok)
            .trimmed();
    if (!ok || name.isEmpty())
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::RenameSwapDrawingCommand(doc, link, name));
}

void SwapActions::deleteDrawing()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (!g || !g->swap.linked())
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::RemoveSwapDrawingCommand(doc, g->swap));
}

void SwapActions::makeOwn()
{
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::MakeDrawingOwnCommand(doc, m_state->currentGroupId()));
}

model::Id SwapActions::stepTarget() const
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (g && g->swap.linked())
        return g->id;
    if (const model::Frame *f = m_state->currentFrame())
        for (auto it = f->groups.rbegin(); it != f->groups.rend(); ++it)
            if (it->swap.linked())
                return it->id;
    return model::kNoId;
}

void SwapActions::step(int delta)
{
    model::Document *doc = m_state->document();
    const model::Id target = stepTarget();
    const model::StrokeGroup *g = doc->group(target);
    if (!g || g->locked)
        return;
    if (auto *command = model::stepSwapDrawing(doc, target, delta)) {
        doc->undoStack()->push(command);
        if (const model::StrokeGroup *now = doc->group(target))
            if (const model::SwapDrawing *d = doc->swapDrawing(now->swap))
                emit message(tr("Drawing \"%1\"").arg(d->name));
    }
}

} // namespace finbook::ui
