// Reading a picture file into the layers that become picture objects (issue 51).
//
// A plain picture (PNG, JPEG, WebP, TIFF, GIF …) is one layer; an OpenRaster file (.ora: a zip
// of stack.xml and one PNG per layer, as Krita, GIMP and MyPaint write it) is one layer per
// visible layer of its stack. Qt's image readers decode first, FFmpeg the formats Qt lacks
// (the reference layer's decoder, reference_media.h). Nothing is decoded before its claimed
// size has been checked against the limits below, and no zip entry is read past its bound, so
// a hostile file costs bounded memory and gets a sentence saying what is wrong.
#pragma once

#include <finbook/geometry/expected.h>

#include <QImage>
#include <QPoint>
#include <QString>

#include <vector>

namespace finbook::model {

// Limits of one import. A picture larger than these is refused, never scaled down.
inline constexpr int kMaxPictureSide = 16384;                         // px, either side
inline constexpr qint64 kMaxPictureLayerPixels = qint64(8192) * 8192; // 64 Mpx per layer
inline constexpr qint64 kMaxPictureDecodedBytes = qint64(256) << 20;  // all layers, decoded
inline constexpr qint64 kMaxPictureFileBytes = qint64(256) << 20;     // a plain picture file
inline constexpr qint64 kMaxOpenRasterEntryBytes = qint64(128) << 20; // one layer's PNG in .ora
inline constexpr qint64 kMaxOpenRasterStackBytes = qint64(4) << 20;   // stack.xml
inline constexpr int kMaxOpenRasterLayers = 1000;
inline constexpr int kMaxOpenRasterDepth = 64; // nested <stack> elements

struct PictureLayer {
    QString name;  // the layer's name; a plain picture's file base name ("cat" for cat.png)
    QImage image;  // Format_ARGB32_Premultiplied, never null or empty
    QPoint offset; // where the image's top-left pixel lies, in the file's canvas pixels
};

// The layers of the picture file at `path`, in painting order: bottom layer first (OpenRaster's
// stack.xml lists the top layer first; the order here is reversed so that drawing the layers
// one after another reproduces the picture).
//
// Plain pictures: one layer named after the file's base name, offset (0, 0); an animated
// picture's first frame.
// OpenRaster: each layer whose `visibility` is not "hidden" and none of whose enclosing
// <stack>s is hidden; its offset is its x, y plus those of its enclosing stacks; its `opacity`
// and its stacks' are multiplied into its pixels (a stack's opacity is applied to each of its
// layers alone, not to the group composited: the same wherever they do not overlap). Layers of
// opacity 0 are left out (nothing of them shows). Blend modes other than normal are ignored.
//
// Errors (one translatable sentence naming the file and what is wrong): the file cannot be
// read, is empty, is larger than kMaxPictureFileBytes, is no picture Qt or FFmpeg decodes, is
// damaged or cut short, claims a size past kMaxPictureSide or kMaxPictureLayerPixels, or its
// layers together pass kMaxPictureDecodedBytes; for OpenRaster also: not a zip, damaged zip
// entries (CRC), no stack.xml, malformed stack.xml, a layer whose picture is missing from the
// zip, an entry larger (or claiming to be larger) than its bound, a stack nested deeper than
// kMaxOpenRasterDepth or with more than kMaxOpenRasterLayers layers, no visible layer.
Expected<std::vector<PictureLayer>, QString> readPictureLayers(const QString &path);

} // namespace finbook::model
