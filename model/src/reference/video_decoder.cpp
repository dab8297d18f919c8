// VideoDecoder: FFmpeg demuxing from memory (a custom AVIOContext), decoding and conversion to
// a QImage. Every FFmpeg object is owned by State and freed in its destructor.
#include "video_decoder.h"

#include <QCoreApplication>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>

namespace finbook::model::reference_detail {

namespace {
constexpr int kIoBufferBytes = 1 << 16;
constexpr int kMaxSide = 16384;
constexpr qint64 kMaxPixels = qint64(8192) * 8192;
// Decoding forward beats seeking when the time asked for is at most this far ahead.
constexpr double kForwardSeconds = 1.0;

QString translated(const char *text)
{
    return QCoreApplication::translate("Reference", text);
}
} // namespace

struct VideoDecoder::State {
    QByteArray bytes;
    qint64 position = 0;
    AVIOContext *io = nullptr;
    AVFormatContext *format = nullptr;
    AVCodecContext *codec = nullptr;
    SwsContext *sws = nullptr;
    AVPacket *packet = nullptr;
    AVFrame *current = nullptr; // the last frame decoded at or before the time asked
    AVFrame *pending = nullptr; // a frame decoded past it, kept for the next call
    bool haveCurrent = false;
    bool havePending = false;
    bool draining = false;
    int stream = -1;
    int width = 0; // as the stream's header says
    int height = 0;
    double timeBase = 0.0;
    qint64 startPts = 0;
    qint64 decoded = 0;

    ~State()
    {
        sws_freeContext(sws);
        av_frame_free(&current);
        av_frame_free(&pending);
        av_packet_free(&packet);
        avcodec_free_context(&codec);
        avformat_close_input(&format);
        if (io)
            av_freep(&io->buffer);
        avio_context_free(&io);
    }

    static int read(void *opaque, uint8_t *buffer, int size)
    {
        auto *s = static_cast<State *>(opaque);
        const qint64 left = s->bytes.size() - s->position;
        if (left <= 0)
            return AVERROR_EOF;
        const int n = int(std::min<qint64>(left, size));
        std::memcpy(buffer, s->bytes.constData() + s->position, std::size_t(n));
        s->position += n;
        return n;
    }

    static int64_t seek(void *opaque, int64_t offset, int whence)
    {
        auto *s = static_cast<State *>(opaque);
        const qint64 size = s->bytes.size();
        if (whence & AVSEEK_SIZE)
            return size;
        qint64 to = offset;
        switch (whence & ~AVSEEK_FORCE) {
        case SEEK_SET:
            break;
        case SEEK_CUR:
            to = s->position + offset;
            break;
        case SEEK_END:
            to = size + offset;
            break;
        default:
            return -1;
        }
        if (to < 0 || to > size)
            return -1;
        s->position = to;
        return to;
    }

    qint64 framePts(const AVFrame *f) const
    {
        const qint64 pts = f->best_effort_timestamp;
        return pts == AV_NOPTS_VALUE ? startPts : pts;
    }

    // The next decoded frame into `into`; false at the end of the stream or on an error.
    bool decodeNext(AVFrame *into)
    {
        for (;;) {
            const int received = avcodec_receive_frame(codec, into);
            if (received == 0) {
                ++decoded;
                return true;
            }
            if (received != AVERROR(EAGAIN) || draining)
                return false;
            if (av_read_frame(format, packet) < 0) {
                avcodec_send_packet(codec, nullptr);
                draining = true;
                continue;
            }
            if (packet->stream_index == stream)
                avcodec_send_packet(codec, packet); // a damaged packet is skipped
            av_packet_unref(packet);
        }
    }

    void seekTo(qint64 target)
    {
        av_seek_frame(format, stream, target, AVSEEK_FLAG_BACKWARD);
        avcodec_flush_buffers(codec);
        av_frame_unref(current);
        av_frame_unref(pending);
        haveCurrent = havePending = draining = false;
    }

    // The frame as a picture of the size the stream announced (`width` × `height`): a frame
    // that decodes to another size (a stream that changes size midway, or lies in its header)
    // is scaled to it, so every picture of the reference costs what its header said.
    QImage convert(const AVFrame *f)
    {
        if (f->width <= 0 || f->height <= 0 || f->width > kMaxSide || f->height > kMaxSide ||
            qint64(f->width) * f->height > kMaxPixels)
            return {};
        const auto source = AVPixelFormat(f->format);
        const AVPixFmtDescriptor *desc = av_pix_fmt_desc_get(source);
        const bool alpha = desc && (desc->flags & AV_PIX_FMT_FLAG_ALPHA);
        QImage image(width, height, alpha ? QImage::Format_ARGB32 : QImage::Format_RGB32);
        if (image.isNull())
            return {};
        // AV_PIX_FMT_RGB32 is 0xAARRGGBB in a native-endian word, as QImage's ARGB32 is.
        sws = sws_getCachedContext(sws, f->width, f->height, source, width, height,
                                   AV_PIX_FMT_RGB32, SWS_BILINEAR, nullptr, nullptr, nullptr);
        if (!sws)
            return {};
        uint8_t *planes[4] = {image.bits(), nullptr, nullptr, nullptr};
        int strides[4] = {int(image.bytesPerLine()), 0, 0, 0};
        sws_scale(sws, f->data, f->linesize, 0, f->height, planes, strides);
        return image;
    }
};

VideoDecoder::VideoDecoder(std::unique_ptr<State> state)
    : m(std::move(state))
{}

VideoDecoder::~VideoDecoder() = default;

std::unique_ptr<VideoDecoder> VideoDecoder::open(const QByteArray &bytes, QString *error)
{
    const auto fail = [error](const char *text) {
        if (error)
            *error = translated(text);
        return nullptr;
    };
    av_log_set_level(AV_LOG_QUIET);
    auto s = std::make_unique<State>();
    s->bytes = bytes;
    auto *buffer = static_cast<unsigned char *>(av_malloc(kIoBufferBytes));
    if (!buffer)
        return fail(QT_TRANSLATE_NOOP("Reference", "There is not enough memory to read it."));
    s->io =
        avio_alloc_context(buffer, kIoBufferBytes, 0, s.get(), &State::read, nullptr, &State::seek);
    if (!s->io) {
        av_free(buffer);
        return fail(QT_TRANSLATE_NOOP("Reference", "There is not enough memory to read it."));
    }
    s->format = avformat_alloc_context();
    if (!s->format)
        return fail(QT_TRANSLATE_NOOP("Reference", "There is not enough memory to read it."));
    s->format->pb = s->io;
    s->format->flags |= AVFMT_FLAG_CUSTOM_IO;
    if (avformat_open_input(&s->format, nullptr, nullptr, nullptr) < 0)
        return fail(QT_TRANSLATE_NOOP("Reference", "It is not a picture or a video Finbook can "
                                                   "read, or it is damaged."));
    // FFmpeg renders SVG with librsvg, without the limits renderSvg (reference_svg.h) keeps.
    if (s->format->iformat && std::strstr(s->format->iformat->name, "svg"))
        return fail(QT_TRANSLATE_NOOP("Reference", "It is not a picture or a video Finbook can "
                                                   "read, or it is damaged."));
    if (avformat_find_stream_info(s->format, nullptr) < 0)
        return fail(QT_TRANSLATE_NOOP("Reference", "It is damaged: its streams cannot be read."));
    const AVCodec *codec = nullptr;
    s->stream = av_find_best_stream(s->format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    if (s->stream < 0 || !codec)
        return fail(QT_TRANSLATE_NOOP("Reference", "It holds no picture Finbook can decode."));
    AVStream *stream = s->format->streams[s->stream];
    const AVCodecParameters *par = stream->codecpar;
    if (par->width <= 0 || par->height <= 0 || par->width > kMaxSide || par->height > kMaxSide ||
        qint64(par->width) * par->height > kMaxPixels)
        return fail(QT_TRANSLATE_NOOP("Reference", "Its pictures are empty or larger than "
                                                   "16384 pixels a side."));
    s->codec = avcodec_alloc_context3(codec);
    s->packet = av_packet_alloc();
    s->current = av_frame_alloc();
    s->pending = av_frame_alloc();
    if (!s->codec || !s->packet || !s->current || !s->pending ||
        avcodec_parameters_to_context(s->codec, par) < 0)
        return fail(QT_TRANSLATE_NOOP("Reference", "There is not enough memory to read it."));
    s->codec->thread_count = 2;
    // Checked against the decoded frames, not only the header: FFmpeg refuses to allocate a
    // frame larger than this, so a header that says 64 px over frames 16,000 px wide costs
    // nothing. The margin leaves room for codecs' coded sizes (whole macroblocks).
    s->width = par->width;
    s->height = par->height;
    s->codec->max_pixels =
        std::min<qint64>(kMaxPixels, qint64(par->width + 64) * (par->height + 64));
    if (avcodec_open2(s->codec, codec, nullptr) < 0)
        return fail(QT_TRANSLATE_NOOP("Reference", "Its pictures cannot be decoded."));
    s->timeBase = av_q2d(stream->time_base);
    if (!(s->timeBase > 0.0))
        s->timeBase = 1.0 / 90000.0;
    s->startPts = stream->start_time == AV_NOPTS_VALUE ? 0 : stream->start_time;
    std::unique_ptr<VideoDecoder> decoder(new VideoDecoder(std::move(s)));
    if (decoder->frameAt(0.0).isNull())
        return fail(QT_TRANSLATE_NOOP("Reference", "Its first picture cannot be decoded."));
    return decoder;
}

QSize VideoDecoder::size() const
{
    return QSize(m->width, m->height);
}

double VideoDecoder::frameRate() const
{
    const AVStream *stream = m->format->streams[m->stream];
    const double rate = av_q2d(stream->avg_frame_rate);
    if (std::isfinite(rate) && rate > 0.0 && rate <= 1000.0)
        return rate;
    const double guessed = av_q2d(stream->r_frame_rate);
    return std::isfinite(guessed) && guessed > 0.0 && guessed <= 1000.0 ? guessed : 25.0;
}

double VideoDecoder::duration() const
{
    const AVStream *stream = m->format->streams[m->stream];
    double seconds = 0.0;
    if (stream->duration != AV_NOPTS_VALUE && stream->duration > 0)
        seconds = double(stream->duration) * m->timeBase;
    else if (m->format->duration != AV_NOPTS_VALUE && m->format->duration > 0)
        seconds = double(m->format->duration) / AV_TIME_BASE;
    return std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
}

qint64 VideoDecoder::decodedFrames() const
{
    return m->decoded;
}

QImage VideoDecoder::frameAt(double seconds, const Wants &wants, const Passed &passed)
{
    State &s = *m;
    if (!std::isfinite(seconds) || seconds < 0.0)
        seconds = 0.0;
    const qint64 target = s.startPts + qint64(std::llround(seconds / s.timeBase));
    const qint64 ahead = qint64(kForwardSeconds / s.timeBase);
    const bool forward =
        s.haveCurrent && s.framePts(s.current) <= target && target - s.framePts(s.current) <= ahead;
    if (!forward)
        s.seekTo(target);
    for (;;) {
        if (!s.havePending) {
            if (!s.decodeNext(s.pending))
                break; // the end: the last frame decoded stays shown
            s.havePending = true;
        }
        if (s.haveCurrent && s.framePts(s.pending) > target)
            break;
        if (passed && wants && s.haveCurrent) {
            const double at = double(s.framePts(s.current) - s.startPts) * s.timeBase;
            if (wants(at))
                if (const QImage image = s.convert(s.current); !image.isNull())
                    passed(at, image);
        }
        av_frame_unref(s.current);
        av_frame_move_ref(s.current, s.pending);
        s.havePending = false;
        s.haveCurrent = true;
        if (s.framePts(s.current) >= target)
            break;
    }
    return s.haveCurrent ? s.convert(s.current) : QImage();
}

} // namespace finbook::model::reference_detail
