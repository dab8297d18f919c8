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
        for (auto it = m_entries.begin(); it != m_entries.end();) {
            if (it->pending || m_doc->soundtrack().clip(it.key())) {
                ++it;
                continue;
            }
            m_bytes -= it->bytes;
            if (it->sound)
                m_budget->refund(it->sound->frames());
            it = m_entries.erase(it);
        }
        m_budget->setSoundtrackBytes(m_bytes);
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
    Entry &entry = m_entries[clip.id];
    entry.pending = true;
    entry.bytes = clip.bytes.size();
    m_bytes += entry.bytes;
    m_budget->setSoundtrackBytes(m_bytes);
    const Id id = clip.id;
    const QByteArray bytes = clip.bytes;
    auto cancelled = m_cancelled;
    auto budget = m_budget;
    m_pool.start([this, id, bytes, cancelled, budget] {
        QThread::currentThread()->setPriority(QThread::LowPriority);
        // One clip at a time (one thread): each is charged before the next one starts.
        auto decoded = decodeSound(bytes, cancelled.get(), budget->limitsFor(bytes.size()));
        if (decoded)
            budget->spend(decoded->frames());
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

void SoundCache::insert(Id clipId, DecodedSoundPtr sound, WaveformPtr waveform, qint64 encodedBytes)
{
    Entry &e = m_entries[clipId];
    m_bytes += encodedBytes - e.bytes;
    e.bytes = encodedBytes;
    m_budget->setSoundtrackBytes(m_bytes);
    if (e.sound)
        m_budget->refund(e.sound->frames());
    if (sound)
        m_budget->spend(sound->frames());
    e = Entry{std::move(sound), std::move(waveform), {}, false, encodedBytes};
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
