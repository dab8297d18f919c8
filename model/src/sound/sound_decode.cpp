// decodeSound with FFmpeg's libraries (why FFmpeg: sound_decode.h). The file is read from
// memory through a custom AVIOContext, so nothing touches the disk, and every FFmpeg object is
// owned by a guard that frees it on every path out.
#include <finbook/model/sound/sound_decode.h>

#include <QCoreApplication>
#include <QtEndian>

#include <algorithm>
#include <cmath>
#include <cstring>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
}

namespace finbook::model {

namespace {
struct SoundText {
    Q_DECLARE_TR_FUNCTIONS(Sound)
};

struct MemoryInput {
    const QByteArray *bytes;
    qint64 at = 0;
};

int readPacket(void *opaque, uint8_t *buffer, int size)
{
    auto *in = static_cast<MemoryInput *>(opaque);
    const qint64 left = in->bytes->size() - in->at;
    if (left <= 0)
        return AVERROR_EOF;
    const int n = int(std::min<qint64>(left, size));
    std::memcpy(buffer, in->bytes->constData() + in->at, std::size_t(n));
    in->at += n;
    return n;
}

int64_t seekInput(void *opaque, int64_t offset, int whence)
{
    auto *in = static_cast<MemoryInput *>(opaque);
    const qint64 size = in->bytes->size();
    switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE:
        return size;
    case SEEK_SET:
        break;
    case SEEK_CUR:
        offset += in->at;
        break;
    case SEEK_END:
        offset += size;
        break;
    default:
        return -1;
    }
    if (offset < 0 || offset > size)
        return -1;
    in->at = offset;
    return offset;
}

struct Guards {
    AVIOContext *io = nullptr;
    AVFormatContext *format = nullptr;
    AVCodecContext *codec = nullptr;
    SwrContext *swr = nullptr;
    AVPacket *packet = nullptr;
    AVFrame *frame = nullptr;
    ~Guards()
    {
        av_frame_free(&frame);
        av_packet_free(&packet);
        swr_free(&swr);
        avcodec_free_context(&codec);
        avformat_close_input(&format);
        if (io)
            av_freep(&io->buffer);
        avio_context_free(&io);
    }
};

QString notSound()
{
    return SoundText::tr("The file is not a sound Finbook can read (WAV, FLAC, MP3, Ogg, Opus, "
                         "AAC or M4A), or it is damaged.");
}

// FFmpeg estimates a WAV's length from the file's size, so a cut-off WAV looks whole to it:
// compare the data chunk's declared size with the bytes there are. -1 when it is not a WAV or
// declares no size (streamed WAVs write 0 or 0xffffffff).
qint64 missingWavBytes(const QByteArray &bytes)
{
    if (bytes.size() < 12 || !bytes.startsWith("RIFF") || bytes.mid(8, 4) != "WAVE")
        return -1;
    qint64 at = 12;
    while (at + 8 <= bytes.size()) {
        const quint32 size = qFromLittleEndian<quint32>(bytes.constData() + at + 4);
        if (bytes.mid(at, 4) == "data") {
            if (size == 0 || size == 0xffffffffu)
                return -1;
            return std::max<qint64>(0, qint64(size) - (bytes.size() - at - 8));
        }
        at += 8 + qint64(size) + (size & 1);
    }
    return -1;
}

// Decoded samples gathered in blocks, so that growing never copies what is there (a vector
// doubling its buffer held three times the sound for a moment) and the whole never exceeds
// `maxSamples`: each conversion is checked before it is allocated.
class SampleBlocks {
public:
    explicit SampleBlocks(qint64 maxSamples)
        : m_max(maxSamples)
    {}
    qint64 size() const { return m_size; }
    bool full() const { return m_over || m_size > m_max; }
    // Converts `frame` (null: flush the resampler) and appends it. False when the resampler
    // fails; full() when it would pass the limit (nothing is appended then).
    bool convert(SwrContext *swr, const AVFrame *frame)
    {
        const int in = frame ? frame->nb_samples : 0;
        const int room = swr_get_out_samples(swr, in);
        if (room < 0)
            return false;
        // Counted before allocating: a frame of millions of samples at a low rate asks for
        // more than the whole clip may hold.
        if (m_size + qint64(room) * kSoundChannels > m_max + kSlack) {
            m_over = true;
            return true;
        }
        m_scratch.resize(std::size_t(room) * kSoundChannels);
        uint8_t *dst = reinterpret_cast<uint8_t *>(m_scratch.data());
        const int got =
            swr_convert(swr, &dst, room,
                        frame ? const_cast<const uint8_t **>(frame->extended_data) : nullptr, in);
        if (got < 0)
            return false;
        append(m_scratch.data(), qint64(got) * kSoundChannels);
        return true;
    }
    // The samples as one vector, at most `limit` of them; the blocks are freed on the way.
    std::vector<qint16> take(qint64 limit)
    {
        std::vector<qint16> all(std::size_t(std::min(m_size, limit)));
        std::size_t at = 0;
        for (std::vector<qint16> &block : m_blocks) {
            const std::size_t n = std::min(block.size(), all.size() - at);
            std::copy_n(block.begin(), n, all.begin() + std::ptrdiff_t(at));
            at += n;
            std::vector<qint16>().swap(block);
        }
        m_blocks.clear();
        m_size = 0;
        return all;
    }

private:
    static constexpr std::size_t kBlock = std::size_t(1) << 20; // samples (2 MB)
    // A conversion may pass the limit by this much (one packet's worth) before it is refused.
    static constexpr qint64 kSlack = kSoundRate * kSoundChannels;
    void append(const qint16 *from, qint64 count)
    {
        while (count > 0) {
            if (m_blocks.empty() || m_blocks.back().size() == kBlock) {
                m_blocks.emplace_back();
                m_blocks.back().reserve(kBlock);
            }
            std::vector<qint16> &block = m_blocks.back();
            const auto n = std::min<qint64>(count, qint64(kBlock - block.size()));
            block.insert(block.end(), from, from + n);
            from += n;
            count -= n;
            m_size += n;
        }
    }
    qint64 m_max;
    qint64 m_size = 0;
    bool m_over = false; // a conversion was refused: it would have passed the limit
    std::vector<std::vector<qint16>> m_blocks;
    std::vector<qint16> m_scratch;
};

bool rateAllowed(int rate)
{
    return rate >= kMinSoundSourceRate && rate <= kMaxSoundSourceRate;
}

QString rateRefused(int rate)
{
    return SoundText::tr("Its sample rate, %1 Hz, is outside the %2 to %3 Hz Finbook plays (real "
                         "recordings use 8,000 to 192,000).")
        .arg(rate)
        .arg(kMinSoundSourceRate)
        .arg(kMaxSoundSourceRate);
}

QString minutes(double seconds)
{
    return QString::number(seconds / 60.0, 'f', seconds < 600 ? 1 : 0);
}

QString tooMuchForItsSize(qint64 bytes, qint64 maxFrames)
{
    return SoundText::tr("It holds more sound than a file of %1 KB can hold when it is real "
                         "sound (more than %2 min; hostile or damaged files announce hours of "
                         "sound in a few kilobytes). Convert it to WAV, FLAC or MP3 and import it "
                         "again.")
        .arg((bytes + 1023) / 1024)
        .arg(minutes(double(maxFrames) / kSoundRate));
}
} // namespace

double soundSecondsAllowed(qint64 encodedBytes, double cap)
{
    return std::min(cap, kFreeSoundSeconds +
                             double(std::max<qint64>(0, encodedBytes)) / kMinSoundBytesPerSecond);
}

void SoundBudget::setSoundtrackBytes(qint64 bytes)
{
    m_allowed = qint64(soundSecondsAllowed(bytes, kMaxSoundtrackSeconds) * kSoundRate);
}

SoundDecodeLimits SoundBudget::limitsFor(qint64 clipBytes, qint64 wantedFrames) const
{
    SoundDecodeLimits limits;
    limits.wantedFrames = wantedFrames;
    const auto own = qint64(soundSecondsAllowed(clipBytes) * kSoundRate);
    const qint64 left = std::max<qint64>(0, m_allowed - m_spent);
    limits.maxFrames = std::min(own, left);
    if (left < own)
        limits.tooLong =
            SoundText::tr("With the soundtrack's other clips it would make more than %1 min of "
                          "sound, the most Finbook decodes from sound files of this size.")
                .arg(minutes(double(m_allowed) / kSoundRate));
    return limits;
}

Expected<DecodedSound, QString> decodeSound(const QByteArray &bytes,
                                            const std::atomic<bool> *cancelled,
                                            const SoundDecodeLimits &limits)
{
    if (bytes.isEmpty())
        return unexpected(SoundText::tr("The file is empty."));
    if (missingWavBytes(bytes) > 0)
        return unexpected(SoundText::tr("The file is incomplete: its sound data is cut off. "
                                        "Import the complete file."));
    av_log_set_level(AV_LOG_QUIET);
    Guards g;
    MemoryInput input{&bytes};
    constexpr int kIoBuffer = 64 * 1024;
    auto *buffer = static_cast<unsigned char *>(av_malloc(kIoBuffer));
    if (!buffer)
        return unexpected(SoundText::tr("There is not enough memory to read the sound."));
    g.io = avio_alloc_context(buffer, kIoBuffer, 0, &input, readPacket, nullptr, seekInput);
    if (!g.io) {
        av_free(buffer);
        return unexpected(SoundText::tr("There is not enough memory to read the sound."));
    }
    g.format = avformat_alloc_context();
    if (!g.format)
        return unexpected(SoundText::tr("There is not enough memory to read the sound."));
    g.format->pb = g.io;
    g.format->flags |= AVFMT_FLAG_CUSTOM_IO;
    if (avformat_open_input(&g.format, nullptr, nullptr, nullptr) < 0)
        return unexpected(notSound()); // avformat_open_input freed the context
    if (avformat_find_stream_info(g.format, nullptr) < 0)
        return unexpected(notSound());
    const AVCodec *decoder = nullptr;
    const int stream = av_find_best_stream(g.format, AVMEDIA_TYPE_AUDIO, -1, -1, &decoder, 0);
    if (stream < 0 || !decoder)
        return unexpected(SoundText::tr("The file holds no sound Finbook can play."));
    const AVStream *st = g.format->streams[stream];
    // Refused before a decoder exists: a rate of 1 Hz resampled to 48 kHz multiplies the
    // file's samples by 48,000.
    if (const int rate = st->codecpar->sample_rate; rate > 0 && !rateAllowed(rate))
        return unexpected(rateRefused(rate));
    g.codec = avcodec_alloc_context3(decoder);
    if (!g.codec || avcodec_parameters_to_context(g.codec, st->codecpar) < 0 ||
        avcodec_open2(g.codec, decoder, nullptr) < 0)
        return unexpected(notSound());
    if (g.codec->sample_rate <= 0 || g.codec->ch_layout.nb_channels <= 0)
        return unexpected(notSound());
    if (!rateAllowed(g.codec->sample_rate))
        return unexpected(rateRefused(g.codec->sample_rate));
    if (g.codec->ch_layout.nb_channels > kMaxSoundSourceChannels)
        return unexpected(SoundText::tr("It has %1 channels; Finbook plays at most %2.")
                              .arg(g.codec->ch_layout.nb_channels)
                              .arg(kMaxSoundSourceChannels));
    AVChannelLayout stereo = AV_CHANNEL_LAYOUT_STEREO;
    if (swr_alloc_set_opts2(&g.swr, &stereo, AV_SAMPLE_FMT_S16, kSoundRate, &g.codec->ch_layout,
                            g.codec->sample_fmt, g.codec->sample_rate, 0, nullptr) < 0 ||
        swr_init(g.swr) < 0)
        return unexpected(notSound());
    g.packet = av_packet_alloc();
    g.frame = av_frame_alloc();
    if (!g.packet || !g.frame)
        return unexpected(SoundText::tr("There is not enough memory to read the sound."));

    const qint64 maxFrames = limits.maxFrames >= 0
                                 ? limits.maxFrames
                                 : qint64(soundSecondsAllowed(bytes.size()) * kSoundRate);
    const qint64 wanted = limits.wantedFrames >= 0 ? std::min(limits.wantedFrames, maxFrames) : -1;
    // What decoding reads, bounded too: source samples of every channel at the source rate.
    const qint64 maxSourceSamples =
        (maxFrames + kSoundRate) * kSoundChannels * kMaxSoundSourceFactor;
    qint64 sourceSamples = 0;
    SampleBlocks blocks(maxFrames * kSoundChannels);
    int badPackets = 0;
    bool failed = false;
    const auto drain = [&]() {
        while (!failed && !blocks.full() && avcodec_receive_frame(g.codec, g.frame) == 0) {
            sourceSamples += qint64(g.frame->nb_samples) * g.frame->ch_layout.nb_channels;
            if (g.frame->sample_rate != g.codec->sample_rate ||
                g.frame->ch_layout.nb_channels != g.codec->ch_layout.nb_channels ||
                !blocks.convert(g.swr, g.frame))
                failed = true; // a stream that changes its rate or channels midway
            av_frame_unref(g.frame);
        }
    };
    const auto enough = [&] {
        return blocks.full() || sourceSamples > maxSourceSamples ||
               (wanted >= 0 && blocks.size() >= wanted * kSoundChannels);
    };
    while (!failed && !enough() && av_read_frame(g.format, g.packet) >= 0) {
        if (cancelled && *cancelled)
            return unexpected(QString());
        if (g.packet->stream_index == stream) {
            if (avcodec_send_packet(g.codec, g.packet) < 0)
                ++badPackets;
            drain();
        }
        av_packet_unref(g.packet);
    }
    const bool stopped = wanted >= 0 && blocks.size() >= wanted * kSoundChannels;
    if (!failed && !enough()) {
        avcodec_send_packet(g.codec, nullptr);
        drain();
        if (!failed && !blocks.full())
            failed = !blocks.convert(g.swr, nullptr);
    }
    if (failed)
        return unexpected(notSound());
    if (!stopped && (blocks.full() || sourceSamples > maxSourceSamples)) {
        if (maxFrames >= qint64(kMaxSoundSeconds * kSoundRate))
            return unexpected(SoundText::tr("The sound is longer than %1 minutes, the longest "
                                            "Finbook plays.")
                                  .arg(int(kMaxSoundSeconds / 60)));
        return unexpected(limits.tooLong.isEmpty() ? tooMuchForItsSize(bytes.size(), maxFrames)
                                                   : limits.tooLong);
    }
    DecodedSound sound;
    sound.samples = blocks.take(wanted >= 0 ? wanted * kSoundChannels : maxFrames * kSoundChannels);
    if (sound.samples.empty())
        return unexpected(SoundText::tr("The file holds no sound Finbook can play (no audio could "
                                        "be decoded from it)."));
    // Cut short: far less sound than the container announces (a truncated download or copy).
    if (!stopped && g.format->duration > 0) {
        const double announced = double(g.format->duration) / AV_TIME_BASE;
        if (sound.seconds() < 0.9 * announced - 0.05)
            return unexpected(
                SoundText::tr("The file is incomplete: it announces %1 s of sound but holds only "
                              "%2 s. Import the complete file.")
                    .arg(announced, 0, 'f', 1)
                    .arg(sound.seconds(), 0, 'f', 1));
    }
    if (badPackets > 0 && badPackets * 10 > 1 + int(sound.seconds()))
        return unexpected(notSound());
    return sound;
}

float Waveform::peakBetween(double from, double to) const
{
    const auto first = qint64(std::floor(from * kWaveformBucketsPerSecond));
    const auto last = qint64(std::ceil(to * kWaveformBucketsPerSecond));
    const qint64 begin = std::max<qint64>(0, first);
    const qint64 end = std::min<qint64>(qint64(peaks.size()), std::max(last, first + 1));
    float peak = 0.0f;
    for (qint64 i = begin; i < end; ++i)
        peak = std::max(peak, peaks[std::size_t(i)]);
    return peak;
}

Waveform computeWaveform(const DecodedSound &sound)
{
    constexpr qint64 kFramesPerBucket = kSoundRate / kWaveformBucketsPerSecond;
    const qint64 frames = sound.frames();
    Waveform w;
    w.peaks.resize(std::size_t((frames + kFramesPerBucket - 1) / kFramesPerBucket));
    const qint16 *s = sound.samples.data();
    for (std::size_t b = 0; b < w.peaks.size(); ++b) {
        const qint64 begin = qint64(b) * kFramesPerBucket * kSoundChannels;
        const qint64 end = std::min<qint64>(begin + kFramesPerBucket * kSoundChannels,
                                            qint64(sound.samples.size()));
        int peak = 0;
        for (qint64 i = begin; i < end; ++i)
            peak = std::max(peak, std::abs(int(s[i])));
        w.peaks[b] = std::min(float(peak) * DecodedSound::kScale, 1.0f);
    }
    return w;
}

} // namespace finbook::model
