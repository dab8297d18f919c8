// SoundCache: decoded PCM and waveforms of the soundtrack's clips, computed once per clip on a
// worker thread. A deleted clip stays cached (undo may bring it back) until the document is
// reset (New, Open), which clears the undo history.
//
// A clip's bytes never change under its id, so the id is the cache key. The GUI thread asks
// (request) and is told when the work is done (soundReady / soundFailed); it never waits.
// The worker gets only the clip's bytes (implicitly shared, read-only) and never touches the
// Document. The destructor cancels the work in flight and waits for it.
//
// All the clips it holds share one SoundBudget (sound_decode.h): the sound of a clip that
// would pass it fails with a message, like a clip that does not decode.
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
    // Seeds the cache with a sound decoded elsewhere (the import already decoded it) from a
    // clip of `encodedBytes`.
    void insert(Id clipId, DecodedSoundPtr sound, WaveformPtr waveform, qint64 encodedBytes = 0);
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
        qint64 bytes = 0; // the clip's encoded bytes, counted into the budget
    };
    void requestAll();

    Document *m_doc;
    QHash<Id, Entry> m_entries;
    QThreadPool m_pool;
    std::shared_ptr<std::atomic<bool>> m_cancelled = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<SoundBudget> m_budget = std::make_shared<SoundBudget>();
    qint64 m_bytes = 0; // of every clip in m_entries
};

} // namespace finbook::model
