// SoundCache: decoded PCM and waveforms of the soundtrack's clips, computed once per clip on a
// worker thread. A deleted clip stays cached (undo may bring it back) until the document is
// reset (New, Open), which clears the undo history.
//
// A clip's bytes never change under its id, so the id is the cache key. The GUI thread asks
// (request) and is told when the work is done (soundReady / soundFailed); it never waits.
// The worker gets only the clip's bytes (implicitly shared, read-only) and never touches the
// Document. The destructor cancels the work in flight and waits for it.
#pragma once

#include <finbook/model/sound/sound_clip.h>
#include <finbook/model/sound/sound_decode.h>

#include <QHash>
#include <QObject>
#include <QThreadPool>

#include <atomic>

namespace finbook::model {

class Document;

class SoundCache : public QObject {
    Q_OBJECT
public:
    // Follows `document`'s soundtrack: new clips are decoded as they arrive.
    explicit SoundCache(Document *document, QObject *parent = nullptr);
    ~SoundCache() override;

    // Starts decoding `clip` unless it is done, failed or under way.
    void request(const SoundClip &clip);
    // Seeds the cache with a sound decoded elsewhere (the import already decoded it).
    void insert(Id clipId, DecodedSoundPtr sound, WaveformPtr waveform);
    DecodedSoundPtr sound(Id clipId) const;
    WaveformPtr waveform(Id clipId) const;
    QString error(Id clipId) const; // empty unless decoding failed
    bool isPending(Id clipId) const;
    // Blocks until the work in flight is done (tests, export).
    void waitForIdle();

signals:
    void soundReady(finbook::model::Id clipId);
    void soundFailed(finbook::model::Id clipId, const QString &message);

private:
    struct Entry {
        DecodedSoundPtr sound;
        WaveformPtr waveform;
        QString error;
        bool pending = false;
    };
    void requestAll();

    Document *m_doc;
    QHash<Id, Entry> m_entries;
    QThreadPool m_pool;
    std::shared_ptr<std::atomic<bool>> m_cancelled = std::make_shared<std::atomic<bool>>(false);
};

} // namespace finbook::model
