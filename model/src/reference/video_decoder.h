// Decoding pictures out of a video (or a still image) held in memory, with FFmpeg's libraries.
//
// Private to the model: reference_media.h is the public face. One decoder is one demuxer and
// one codec context: not thread-safe, the caller serialises (ReferenceMedia holds a mutex).
// Asking for a time just after the last one decodes forward; any other time seeks to the
// keyframe at or before it and decodes forward from there.
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

#include <functional>
#include <memory>

namespace finbook::model::reference_detail {

class VideoDecoder {
public:
    // Null with `error` set (one sentence) when the bytes hold no decodable picture stream.
    static std::unique_ptr<VideoDecoder> open(const QByteArray &bytes, QString *error);
    ~VideoDecoder();
    VideoDecoder(const VideoDecoder &) = delete;
    VideoDecoder &operator=(const VideoDecoder &) = delete;

    QSize size() const;
    double frameRate() const; // frames per second (25 when the stream does not say)
    double duration() const;  // seconds; 0 for a still picture
    // The frame shown at `seconds` from the start (clamped to the first and last frame):
    // Format_ARGB32 or Format_RGB32. Null when decoding fails.
    // `passed` (optional) gets the frames decoded on the way, with their time, that `wants`
    // asks for (it is asked before the frame is converted): scrubbing backwards then finds
    // them cached.
    using Wants = std::function<bool(double seconds)>;
    using Passed = std::function<void(double seconds, const QImage &)>;
    QImage frameAt(double seconds, const Wants &wants = {}, const Passed &passed = {});
    // Frames decoded since open (seeks make this grow faster than the frames asked for).
    qint64 decodedFrames() const;

private:
    struct State;
    explicit VideoDecoder(std::unique_ptr<State> state);
    std::unique_ptr<State> m;
};

} // namespace finbook::model::reference_detail
