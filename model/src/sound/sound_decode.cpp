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

// Converts `frame` (null: flush the resampler) and appends to `out`.
bool convert(SwrContext *swr, const AVFrame *frame, std::vector<float> &out)
{
    const int in = frame ? frame->nb_samples : 0;
    const int room = swr_get_out_samples(swr, in);
    if (room < 0)
        return false;
    const std::size_t at = out.size();
    out.resize(at + std::size_t(room) * kSoundChannels);
    uint8_t *dst = reinterpret_cast<uint8_t *>(out.data() + at);
    const int got = swr_convert(
        swr, &dst, room, frame ? const_cast<const uint8_t **>(frame->extended_data) : nullptr, in);
    if (got < 0)
        return false;
    out.resize(at + std::size_t(got) * kSoundChannels);
    return true;
}
} // namespace

Expected<DecodedSound, QString> decodeSound(const QByteArray &bytes,
                                            const std::atomic<bool> *cancelled)
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
    g.codec = avcodec_alloc_context3(decoder);
    if (!g.codec || avcodec_parameters_to_context(g.codec, st->codecpar) < 0 ||
        avcodec_open2(g.codec, decoder, nullptr) < 0)
        return unexpected(notSound());
    if (g.codec->sample_rate <= 0 || g.codec->ch_layout.nb_channels <= 0)
        return unexpected(notSound());
    AVChannelLayout stereo = AV_CHANNEL_LAYOUT_STEREO;
    if (swr_alloc_set_opts2(&g.swr, &stereo, AV_SAMPLE_FMT_FLT, kSoundRate, &g.codec->ch_layout,
                            g.codec->sample_fmt, g.codec->sample_rate, 0, nullptr) < 0 ||
        swr_init(g.swr) < 0)
        return unexpected(notSound());
    g.packet = av_packet_alloc();
    g.frame = av_frame_alloc();
    if (!g.packet || !g.frame)
        return unexpected(SoundText::tr("There is not enough memory to read the sound."));

    DecodedSound sound;
    const auto maxSamples = std::size_t(kMaxSoundSeconds * kSoundRate) * kSoundChannels;
    int badPackets = 0;
    const auto drain = [&]() -> bool {
        while (avcodec_receive_frame(g.codec, g.frame) == 0) {
            if (!convert(g.swr, g.frame, sound.samples))
                return false;
            av_frame_unref(g.frame);
        }
        return true;
    };
    bool tooLong = false;
    while (av_read_frame(g.format, g.packet) >= 0) {
        if (cancelled && *cancelled)
            return unexpected(QString());
        if (g.packet->stream_index == stream) {
            if (avcodec_send_packet(g.codec, g.packet) < 0)
                ++badPackets;
            if (!drain())
                return unexpected(notSound());
        }
        av_packet_unref(g.packet);
        if (sound.samples.size() > maxSamples) {
            tooLong = true;
            break;
        }
    }
    avcodec_send_packet(g.codec, nullptr);
    if (!drain() || !convert(g.swr, nullptr, sound.samples))
        return unexpected(notSound());
    if (tooLong)
        return unexpected(SoundText::tr("The sound is longer than %1 minutes, the longest "
                                        "Finbook plays.")
                              .arg(int(kMaxSoundSeconds / 60)));
    if (sound.samples.empty())
        return unexpected(SoundText::tr("The file holds no sound Finbook can play (no audio could "
                                        "be decoded from it)."));
    // Cut short: far less sound than the container announces (a truncated download or copy).
    if (g.format->duration > 0) {
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
    for (float &s : sound.samples)
        if (!std::isfinite(s))
            s = 0.0f;
    sound.samples.shrink_to_fit();
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
    const float *s = sound.samples.data();
    for (std::size_t b = 0; b < w.peaks.size(); ++b) {
        const qint64 begin = qint64(b) * kFramesPerBucket * kSoundChannels;
        const qint64 end = std::min<qint64>(begin + kFramesPerBucket * kSoundChannels,
                                            qint64(sound.samples.size()));
        float peak = 0.0f;
        for (qint64 i = begin; i < end; ++i)
            peak = std::max(peak, std::abs(s[i]));
        w.peaks[b] = std::min(peak, 1.0f);
    }
    return w;
}

} // namespace finbook::model
