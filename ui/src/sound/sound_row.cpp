#include <finbook/model/document.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/sound/sound_controller.h>
#include <finbook/ui/sound/sound_row.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/editor_state.h>

#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
QColor clipColour(int index)
{
    static const QColor colours[] = {QColor(0x2f, 0x80, 0xd0), QColor(0xd0, 0x70, 0x20),
                                     QColor(0x30, 0xa0, 0x60), QColor(0xa0, 0x40, 0xb0)};
    return colours[index % 4];
}
} // namespace

SoundRow::SoundRow(SoundController *controller, TimelineView *view, QWidget *parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_view(view)
{
    setObjectName(QStringLiteral("timeline.soundRow"));
    setFixedHeight(kHeight);
    setFocusPolicy(Qt::ClickFocus);
    setToolTip(tr("The soundtrack: drag a sound to move it, right click for its volume"));
    const auto repaint = [this] { update(); };
    model::Document *doc = controller->editorState()->document();
    connect(&doc->soundtrack(), &model::Soundtrack::clipsChanged, this, repaint);
    connect(&doc->soundtrack(), &model::Soundtrack::clipEdited, this, repaint);
    connect(controller->cache(), &model::SoundCache::soundReady, this, repaint);
    connect(controller->cache(), &model::SoundCache::soundFailed, this, repaint);
    connect(view->horizontalScrollBar(), &QScrollBar::valueChanged, this, repaint);
    connect(controller->editorState(), &EditorState::currentFrameChanged, this, repaint);
    for (auto signal : {&model::Document::framesInserted, &model::Document::framesRemoved})
        connect(doc, signal, this, repaint);
    connect(doc, &model::Document::frameMoved, this, repaint);
    connect(doc, &model::Document::frameChanged, this, repaint);
    connect(doc, &model::Document::documentReset, this, repaint);
    connect(doc, &model::Document::settingsChanged, this, repaint);
    // The view lays out its cells after the model changes: draw again once it has.
    connect(view->frameModel(), &QAbstractItemModel::layoutChanged, this, repaint);
    connect(view->frameModel(), &QAbstractItemModel::rowsInserted, this, repaint);
}

std::vector<SoundRow::Cell> SoundRow::visibleCells() const
{
    std::vector<Cell> cells;
    const model::Document &doc = *m_controller->editorState()->document();
    const int offset = m_view->viewport()->mapTo(parentWidget(), QPoint(0, 0)).x() - x();
    qint64 tick = 0;
    for (int row = 0; row < doc.frameCount(); ++row) {
        const int hold = std::max(1, doc.frameAt(row).hold);
        const QRect r = m_view->visualRect(m_view->frameModel()->index(row));
        if (r.isValid() && r.right() + offset >= 0 && r.left() + offset <= width())
            cells.push_back({r.left() + offset, r.width() + m_view->spacing(), tick, hold, row});
        tick += hold;
    }
    return cells;
}

double SoundRow::tickAt(int x) const
{
    const std::vector<Cell> cells = visibleCells();
    if (cells.empty())
        return 0.0;
    if (x < cells.front().left)
        return double(cells.front().tick);
    for (const Cell &c : cells)
        if (x < c.left + c.width)
            return double(c.tick) + double(x - c.left) / c.width * c.hold;
    return double(cells.back().tick + cells.back().hold);
}

int SoundRow::xOfTick(double tick) const
{
    for (const Cell &c : visibleCells())
        if (tick >= double(c.tick) && tick < double(c.tick + c.hold))
            return c.left + int((tick - double(c.tick)) / c.hold * c.width);
    return -1;
}

double SoundRow::clipEndTick(model::Id clipId) const
{
    const model::Document &doc = *m_controller->editorState()->document();
    const model::SoundClip *clip = doc.soundtrack().clip(clipId);
    if (!clip)
        return 0.0;
    const model::DecodedSoundPtr sound = m_controller->cache()->sound(clipId);
    const double seconds = sound ? sound->seconds() : 1.0;
    return double(clip->start) + seconds * doc.settings().fps;
}

double SoundRow::secondsPastEnd() const
{
    const model::Document &doc = *m_controller->editorState()->document();
    qint64 total = 0;
    for (int row = 0; row < doc.frameCount(); ++row)
        total += std::max(1, doc.frameAt(row).hold);
    double past = 0.0;
    for (const model::SoundClip &clip : doc.soundtrack().clips())
        past = std::max(past, clipEndTick(clip.id) - double(total));
    return past / std::max(1, doc.settings().fps);
}

void SoundRow::paintPastEnd(QPainter &painter, const std::vector<Cell> &cells)
{
    const model::Document &doc = *m_controller->editorState()->document();
    const double seconds = secondsPastEnd();
    if (!(seconds > 0.0) || cells.empty() || cells.back().row != doc.frameCount() - 1)
        return;
    const int left = cells.back().left + cells.back().width;
    if (left >= width())
        return;
    const QRect past(left, 2, width() - left, height() - 4);
    QColor hatch = palette().color(QPalette::Text);
    hatch.setAlpha(90);
    painter.fillRect(past, QBrush(hatch, Qt::BDiagPattern));
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(
        past.adjusted(4, 0, -2, 0), Qt::AlignVCenter | Qt::AlignLeft,
        tr("+%1 s after the last frame (not played)").arg(QLocale().toString(seconds, 'f', 1)));
}

model::Id SoundRow::clipAt(int x) const
{
    const double tick = tickAt(x);
    const auto &clips = m_controller->editorState()->document()->soundtrack().clips();
    for (auto it = clips.rbegin(); it != clips.rend(); ++it)
        if (tick >= double(it->start) && tick < clipEndTick(it->id))
            return it->id;
    return model::kNoId;
}

void SoundRow::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Base).darker(108));
    const std::vector<Cell> cells = visibleCells();
    const EditorState *state = m_controller->editorState();
    const auto &clips = state->document()->soundtrack().clips();
    for (const Cell &c : cells) {
        painter.setPen(palette().color(QPalette::Mid));
        painter.drawLine(c.left + c.width - 1, 0, c.left + c.width - 1, height());
    }
    for (int i = 0; i < int(clips.size()); ++i)
        paintClip(painter, cells, i);
    paintPastEnd(painter, cells);
    if (clips.empty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(8, 0, -8, 0), Qt::AlignVCenter | Qt::AlignLeft,
                         tr("No sound: File \u2192 Import Sound\u2026"));
    }
    // The current frame's column, as in the strip above.
    const int current = state->currentFrameIndex();
    const model::Document &doc = *state->document();
    if (current >= 0 && current < doc.frameCount()) {
        const qint64 tick = startTickOfFrame(doc, current);
        for (const Cell &c : cells)
            if (c.tick == tick) {
                QColor mark = palette().color(QPalette::Highlight);
                mark.setAlpha(60);
                painter.fillRect(QRect(c.left, 0, c.width - 1, height()), mark);
            }
    }
}

void SoundRow::paintClip(QPainter &painter, const std::vector<Cell> &cells, int index)
{
    const model::Document &doc = *m_controller->editorState()->document();
    const model::SoundClip &clip = doc.soundtrack().clips()[std::size_t(index)];
    const int fps = doc.settings().fps;
    const double shift = clip.id == m_dragClip ? double(m_dragTicks) : 0.0;
    const double start = double(clip.start) + shift;
    const double end = clipEndTick(clip.id) + shift;
    const model::WaveformPtr wave = m_controller->cache()->waveform(clip.id);
    const QString error = m_controller->cache()->error(clip.id);
    QColor colour = clip.muted ? palette().color(QPalette::Mid) : clipColour(index);
    const int mid = height() / 2;
    int firstX = -1;
    for (const Cell &c : cells) {
        if (double(c.tick + c.hold) <= start || double(c.tick) >= end)
            continue;
        for (int px = 0; px < c.width - 1; ++px) {
            const double t0 = double(c.tick) + double(px) / c.width * c.hold;
            const double t1 = double(c.tick) + double(px + 1) / c.width * c.hold;
            if (t1 <= start || t0 >= end)
                continue;
            if (firstX < 0)
                firstX = c.left + px;
            if (!wave) {
                painter.fillRect(QRect(c.left + px, mid - 1, 1, 2), colour);
                continue;
            }
            const float peak = wave->peakBetween((t0 - start) / fps, (t1 - start) / fps);
            // Square root: quiet sound (speech, a soft beat) still shows, as in audio editors.
            const float level = std::sqrt(std::min(1.0f, peak * float(clip.volume)));
            const int h = std::max(1, int(level * float(mid - 3)));
            painter.fillRect(
                QRect(c.left + px, mid - std::min(h, mid - 2), 1, 2 * std::min(h, mid - 2)),
                colour);
        }
    }
    if (firstX < 0)
        return;
    QString label = clip.name;
    if (!error.isEmpty())
        label = tr("%1 (cannot be played)").arg(clip.name);
    else if (!wave)
        label = tr("%1 (reading…)").arg(clip.name);
    else if (clip.muted)
        label = tr("%1 (muted)").arg(clip.name);
    painter.setPen(palette().color(QPalette::Text));
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    painter.setFont(small);
    painter.drawText(QRect(firstX + 3, 1, width() - firstX, 14), Qt::AlignLeft | Qt::AlignTop,
                     label);
    painter.fillRect(QRect(firstX, 0, 2, height()), colour);
}

void SoundRow::mousePressEvent(QMouseEvent *event)
{
    const int x = int(event->position().x());
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    m_dragClip = clipAt(x);
    m_pressTick = tickAt(x);
    m_dragTicks = 0;
    if (m_dragClip == model::kNoId) {
        for (const Cell &c : visibleCells())
            if (x >= c.left && x < c.left + c.width)
                m_controller->editorState()->setCurrentFrameIndex(c.row);
    }
    event->accept();
}

void SoundRow::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragClip == model::kNoId) {
        event->ignore();
        return;
    }
    m_dragTicks = qint64(std::lround(tickAt(int(event->position().x())) - m_pressTick));
    const model::SoundClip *clip =
        m_controller->editorState()->document()->soundtrack().clip(m_dragClip);
    if (clip)
        m_dragTicks = std::max(m_dragTicks, -clip->start);
    update();
    event->accept();
}

void SoundRow::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragClip == model::kNoId || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    const model::Id id = std::exchange(m_dragClip, model::kNoId);
    const qint64 moved = std::exchange(m_dragTicks, 0);
    const model::SoundClip *clip = m_controller->editorState()->document()->soundtrack().clip(id);
    if (clip && moved != 0)
        m_controller->move(id, clip->start + moved);
    update();
    event->accept();
}

void SoundRow::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Escape && m_dragClip != model::kNoId) {
        m_dragClip = model::kNoId;
        m_dragTicks = 0;
        update();
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

void SoundRow::contextMenuEvent(QContextMenuEvent *event)
{
    const model::Id id = clipAt(event->pos().x());
    const model::SoundClip *clip = m_controller->editorState()->document()->soundtrack().clip(id);
    QMenu menu(this);
    if (clip) {
        QAction *mute = menu.addAction(tr("&Mute"));
        mute->setCheckable(true);
        mute->setChecked(clip->muted);
        connect(mute, &QAction::toggled, this,
                [this, id](bool on) { m_controller->setMuted(id, on); });
        connect(menu.addAction(tr("&Volume...")), &QAction::triggered, this,
                [this, id] { m_controller->askVolume(id); });
        connect(menu.addAction(tr("Delete &Sound")), &QAction::triggered, this,
                [this, id] { m_controller->remove(id); });
        menu.addSeparator();
    }
    menu.addAction(m_controller->importAction());
    menu.exec(event->globalPos());
}

} // namespace finbook::ui
