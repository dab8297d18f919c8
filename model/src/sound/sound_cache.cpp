#include <finbook/model/document.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/soundtrack.h>

#include <QCoreApplication>
#include <QThread>

namespace finbook::model {

SoundCache::SoundCache(Document *document, QObject *parent)
    : QObject(parent)
    , m_doc(document)
{
    m_pool.setMaxThreadCount(1);
    connect(&document->soundtrack(), &Soundtrack::clipsChanged, this, &SoundCache::requestAll);
    connect(document, &Document::documentReset, this, [this] {
        for (auto it = m_entries.begin(); it != m_entries.end();)
            it = it->pending || m_doc->soundtrack().clip(it.key()) ? std::next(it)
                                                                   : m_entries.erase(it);
    });
    requestAll();
}

SoundCache::~SoundCache()
{
    m_cancelled->store(true);
    m_pool.waitForDone();
}

void SoundCache::requestAll()
{
    for (const SoundClip &clip : m_doc->soundtrack().clips())
        request(clip);
}

void SoundCache::request(const SoundClip &clip)
{
    if (m_entries.contains(clip.id))
        return;
    m_entries[clip.id].pending = true;
    const Id id = clip.id;
    const QByteArray bytes = clip.bytes;
    auto cancelled = m_cancelled;
    m_pool.start([this, id, bytes, cancelled] {
        QThread::currentThread()->setPriority(QThread::LowPriority);
        auto decoded = decodeSound(bytes, cancelled.get());
        if (cancelled->load())
            return;
        DecodedSoundPtr sound;
        WaveformPtr waveform;
        QString error;
        if (decoded) {
            auto s = std::make_shared<DecodedSound>(std::move(*decoded));
            waveform = std::make_shared<const Waveform>(computeWaveform(*s));
            sound = std::move(s);
        } else {
            error = decoded.error();
        }
        QMetaObject::invokeMethod(
            this,
            [this, id, sound, waveform, error] {
                Entry &e = m_entries[id];
                e.pending = false;
                e.sound = sound;
                e.waveform = waveform;
                e.error = error;
                if (sound)
                    emit soundReady(id);
                else
                    emit soundFailed(id, error);
            },
            Qt::QueuedConnection);
    });
}

void SoundCache::insert(Id clipId, DecodedSoundPtr sound, WaveformPtr waveform)
{
    Entry &e = m_entries[clipId];
    e = Entry{std::move(sound), std::move(waveform), {}, false};
    emit soundReady(clipId);
}

DecodedSoundPtr SoundCache::sound(Id clipId) const
{
    return m_entries.value(clipId).sound;
}

WaveformPtr SoundCache::waveform(Id clipId) const
{
    return m_entries.value(clipId).waveform;
}

QString SoundCache::error(Id clipId) const
{
    return m_entries.value(clipId).error;
}

bool SoundCache::isPending(Id clipId) const
{
    return m_entries.value(clipId).pending;
}

void SoundCache::waitForIdle()
{
    m_pool.waitForDone();
    QCoreApplication::sendPostedEvents(this);
}

} // namespace finbook::model
