// A software rasterizer for the canvas's cached layers: each stroke is the union of
// round-capped segments ("capsules") whose radius follows the pressure, which is exactly the
// shape QPainter draws for a round-cap, round-join polyline. QPainter's stroker spends a few
// microseconds per point building that outline; here a segment costs a few dozen pixel
// evaluations, so a 50,000-point frame renders in milliseconds instead of ~150 ms.
//
// Coverage is antialiased from the distance to the segment; a stroke's capsules combine by
// maximum coverage in a mask before the stroke is composited once (source-over), so joints
// never double-blend and translucent colours look as QPainter draws them.
#pragma once

#include <finbook/model/render.h>

#include <QImage>
#include <QPainterPath>
#include <QTransform>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace finbook::ui {

// One row of a capsule's pixels to cover: `n` mask bytes from `row`, the first pixel's centre
// at (px0, py) from the capsule's start.
struct CoverSpan {
    std::uint8_t *row;
    float px0, py;
    int n;
};

class StrokeRaster {
public:
    // Draws into `image` (Format_ARGB32_Premultiplied), never outside `deviceClip`. A canvas
    // point p lands at toDevice.map(p) in device pixels. `toDevice` is a similarity (a zoom, a
    // turn, a mirror and a move: the view and the camera), which keeps a capsule a capsule;
    // widths scale by its zoom.
    // `recycledMask` may hand over an all-zero mask from an earlier rasterizer to reuse.
    StrokeRaster(QImage *image, const QRect &deviceClip, const QTransform &toDevice,
                 std::vector<std::uint8_t> recycledMask = {});

    void drawStroke(const std::vector<model::StrokePoint> &points, QRgb color, float width,
                    qreal opacity);
    // A fill (canvas pixels, the path's own fill rule), antialiased by QPainter.
    void drawFill(const QPainterPath &path, QRgb color, qreal opacity);
    // A picture object's picture as it shows now (picture/picture_object.h), under its fills;
    // `tint` recolours it at its own alpha (the onion skin).
    void drawPicture(const model::StrokeGroup &group, const std::optional<QColor> &tint,
                     qreal opacity);
    // paintFrame()'s rules: hidden objects skipped unless options.showHidden, the tint
    // replaces every colour, each object's fills under its strokes (regions closed with
    // settings.closeGap; shaded fills lit by its light). No background. A frame drawn with
    // opacity below 1 or a tint (onion skin) is drawn whole into a layer first and laid on the
    // image once with options.opacity, so where its items overlap (a cut-out limb's pieces, its
    // sockets and split lines at a joint) it shows as the opaque frame would, not darker; with
    // a tint each item replaces what lies under it in that layer (the opaque frame's look:
    // the ghost of a fill on a fill is one ghost of a fill).
    void drawFrame(const model::Frame &frame, const model::RenderOptions &options,
                   const model::DocumentSettings &settings);
    // Computes what drawFrame needs of the frame's fills once, on this thread, so the bands
    // of drawParallel find it cached instead of each computing it.
    static void prepareFills(const model::Frame &frame, const model::RenderOptions &options,
                             const model::DocumentSettings &settings);

    // Runs `draw` once per horizontal band of the clip, one band per core (up to 4), each on
    // its own rasterizer: bands share no pixel, so the result equals one rasterizer's. Blocks
    // until done; `draw` must only read what does not change meanwhile. GUI thread only (it
    // keeps its masks for the next call).
    static void drawParallel(QImage *image, const QRect &deviceClip, const QTransform &toDevice,
                             const std::function<void(StrokeRaster &)> &draw);

private:
    void capsule(float ax, float ay, float ar, float bx, float by, float br);
    void touch(int x0, int y0, int x1, int y1);
    void composite(QRgb color, qreal opacity);
    void flushGhost(qreal opacity);

    uchar *m_bits;
    qsizetype m_stride;
    QRect m_clip;
    QTransform m_toDevice;
    // m_toDevice as numbers: device x = m_xx * x + m_xy * y + m_ox, device y = m_yx * x +
    // m_yy * y + m_oy; m_scale is its zoom (device pixels per canvas pixel).
    float m_xx, m_xy, m_yx, m_yy;
    float m_scale;
    float m_ox;
    float m_oy;
    int m_width;
    int m_height;
    int m_tilesX;
    bool m_wide = false; // the processor has AVX2: eight pixels a step (stroke_raster.cpp)
    // Coverage of the stroke being drawn, 0..255, over the clip rect (mask and tiles are in
    // clip-relative coordinates).
    std::vector<std::uint8_t> m_mask;
    std::vector<std::uint8_t> m_touched; // per 8×8 tile: has coverage
    std::vector<int> m_tiles;            // touched tile indices
    std::vector<CoverSpan> m_spans;      // the rows of the capsule being drawn
    // The layer a frame is drawn into first (drawFrame), premultiplied, clip-relative, all zero
    // between frames; m_ghostActive while a frame is drawn into it. m_ghostReplace: each item
    // replaces what lies under it (a tinted frame) rather than going over it.
    std::vector<QRgb> m_ghost;
    bool m_ghostActive = false;
    bool m_ghostReplace = false;
    QRect m_ghostBox; // clip-relative pixels the layer may hold
};

} // namespace finbook::ui
