// SoundController: the soundtrack's place in the window. It owns the decoded-sound cache and
// the player, imports sound files (File → Import Sound…: read and decoded on a worker thread,
// then one AddSoundClipCommand at the current frame), and offers the clip actions of the sound
// row (mute, volume, delete), each an undoable command. While not playing, each frame the
// user steps or scrubs to plays the slice of sound under it.
//
// objectName          what it does
// file.importSound    File → Import Sound…
#pragma once

#include <finbook/model/types.h>

#include <QObject>

class QAction;
class QWidget;

namespace finbook::model {
class Document;
class SoundCache;
} // namespace finbook::model

namespace finbook::ui {

class EditorState;
class PlaybackController;
class SoundPlayer;

// The tick (frame time, holds counted) at which frame `index` starts, from the first frame.
qint64 startTickOfFrame(const model::Document &document, int index);

class SoundController : public QObject {
    Q_OBJECT
public:
    // `dialogParent` parents the file and volume dialogs. Sets itself as `playback`'s clock.
    SoundController(EditorState *state, PlaybackController *playback, QWidget *dialogParent,
                    QObject *parent = nullptr);

    QAction *importAction() const { return m_import; }
    model::SoundCache *cache() const { return m_cache; }
    SoundPlayer *player() const { return m_player; }
    EditorState *editorState() const { return m_state; }

    // Reads and decodes `path` off the GUI thread; then imports it at the current frame
    // (importFinished) or says why not (importFailed). Refused unread when too large.
    void importSound(const QString &path);
    // Clip actions (the sound row's menu): each pushes one command, or nothing if unchanged.
    void setMuted(model::Id clipId, bool muted);
    void setVolume(model::Id clipId, double volume);
    void askVolume(model::Id clipId);
    void remove(model::Id clipId);
    void move(model::Id clipId, qint64 start);

signals:
    void importFinished(model::Id clipId, const QString &message);
    void importFailed(const QString &title, const QString &message);
    // One line for the status bar.
    void message(const QString &text);

private:
    void frameShown(int index);

    EditorState *m_state;
    PlaybackController *m_playback;
    QWidget *m_dialogParent;
    model::SoundCache *m_cache;
    SoundPlayer *m_player;
    QAction *m_import;
};

} // namespace finbook::ui
