#include "sound_source.h"

#include <finbook/model/document.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/sound/sound_player.h>

#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QMediaDevices>

namespace finbook::ui {

SoundPlayer::SoundPlayer(model::Document *document, model::SoundCache *cache, QObject *parent)
    : QObject(parent)
    , m_doc(document)
    , m_cache(cache)
    , m_source(new SoundSource(this))
{
    m_source->open(QIODevice::ReadOnly);
}

SoundPlayer::~SoundPlayer()
{
    if (m_sink)
        m_sink->stop();
}

bool SoundPlayer::openSink()
{
    if (m_sink)
        return true;
    if (m_triedSink || !m_allowed)
        return false;
    m_triedSink = true;
    const QAudioDevice device = QMediaDevices::defaultAudioOutput();
    if (device.isNull())
        return false;
    QAudioFormat format;
    format.setSampleRate(model::kSoundRate);
    format.setChannelCount(model::kSoundChannels);
    format.setSampleFormat(QAudioFormat::Float);
    if (!device.isFormatSupported(format))
        return false;
    m_sink = new QAudioSink(device, format, this);
    m_sink->setBufferSize(model::kSoundRate * model::kSoundChannels * int(sizeof(float)) / 10);
    connect(m_sink, &QAudioSink::stateChanged, this, [this](QAudio::State state) {
        if (state == QAudio::IdleState && m_sink && m_sink->error() == QAudio::UnderrunError)
            ++m_underruns;
    });
    return true;
}

void SoundPlayer::begin(qint64 fromSample, qint64 endSample, int fps)
{
    std::vector<model::SoundClip> clips = m_doc->soundtrack().clips();
    std::unordered_map<model::Id, model::DecodedSoundPtr> sounds;
    for (const model::SoundClip &clip : clips)
        if (auto sound = m_cache->sound(clip.id))
            sounds.emplace(clip.id, std::move(sound));
    if (m_sink)
        m_sink->stop();
    m_source->setRange(std::move(clips), std::move(sounds), fps, fromSample, endSample);
    m_fallback.start();
    if (!openSink()) {
        if (!m_saidSilent && !m_doc->soundtrack().isEmpty()) {
            m_saidSilent = true;
            emit silent(tr("No audio output was found: playing without sound."));
        }
        return;
    }
    m_sink->start(m_source);
    if (m_sink->error() != QAudio::NoError) {
        // The device went away or refused the stream: carry on silently on the timer.
        m_sink->deleteLater();
        m_sink = nullptr;
        if (!m_saidSilent) {
            m_saidSilent = true;
            emit silent(tr("The audio output failed: playing without sound."));
        }
    }
}

void SoundPlayer::startAt(qint64 tick, int fps)
{
    m_playing = true;
    begin(model::sampleOfTick(double(tick), fps), -1, fps);
}

qint64 SoundPlayer::nsecsElapsed() const
{
    if (m_sink && m_playing && m_sink->state() != QAudio::StoppedState)
        return m_sink->processedUSecs() * 1000;
    return m_fallback.isValid() ? m_fallback.nsecsElapsed() : 0;
}

void SoundPlayer::stop()
{
    m_playing = false;
    if (m_sink)
        m_sink->stop();
}

void SoundPlayer::playSlice(qint64 tick, int ticks, int fps)
{
    if (m_playing || m_doc->soundtrack().isEmpty())
        return;
    const qint64 from = model::sampleOfTick(double(tick), fps);
    const qint64 end = model::sampleOfTick(double(tick + std::max(1, ticks)), fps);
    begin(from, end, fps);
}

qint64 SoundPlayer::sourcePosition() const
{
    return m_source->position();
}

} // namespace finbook::ui
