// Picture objects in a .finbook (private to the model; layout in finbook_file_format.h):
//
//   "PICT"  := u32 count { u32 width u32 height u64 pngBytes png[pngBytes]
//              u32 vertices (f64 u f64 v)[vertices] u32 triangles (u32 a u32 b u32 c)[triangles]
//              }[count]
//              (picture/picture_object.h PictureData and PictureMesh): each picture once, with
//              its texture mesh, in the order objects first show them. At most once, after FRAM;
//              written only when some object is a picture, so a Finbook that does not know it
//              refuses the file as made by a newer Finbook (it would lose the pictures).
//   "PICO"  := u32 picture f64 m11 f64 m12 f64 m21 f64 m22 f64 dx f64 dy
//              u32 posed (f64 x f64 y)[posed]
//              (object chunk): the object shows picture `picture` of PICT placed by the affine
//              map (x, y) → (m11 x + m21 y + dx, m12 x + m22 y + dy) from picture pixels to the
//              rest drawing (QTransform's order); `posed` is 0, or the texture mesh's vertex
//              count when the object's saved pose (DEFM) carries the picture too.
#pragma once

#include "../finbook_file_byte_writer.h"

#include <finbook/model/picture/picture_object.h>

#include <map>
#include <utility>
#include <vector>

namespace finbook::model::file_format {

constexpr std::size_t kPictureFixedBytes = 4 + 4 + 8 + 4 + 4;
constexpr std::size_t kPictureVertexBytes = 8 + 8;
constexpr std::size_t kPictureTriangleBytes = 4 * 3;
constexpr quint32 kMaxPictureMeshVertices = 1'000'000;

// The pictures of a document in the order objects first show them: one entry per picture and
// texture mesh, however many objects and frames show it.
class PictureTable {
public:
    void add(const StrokeGroup &group);
    bool empty() const { return m_entries.empty(); }
    quint32 indexOf(const ObjectPicture &picture) const;
    qsizetype expectedBytes() const;
    void write(ByteWriter &w) const;

private:
    using Key = std::pair<const PictureData *, const PictureMesh *>;
    std::vector<const ObjectPicture *> m_entries;
    std::map<Key, quint32> m_index;
};

// Whether the group's chunk is written: it shows a whole picture.
bool hasPictureChunk(const StrokeGroup &group);
// The PICO chunk; `posed`: whether the saved pose carries the picture (DEFM is written).
void writePictureChunk(ByteWriter &w, const StrokeGroup &group, const PictureTable &table,
                       bool posed);

} // namespace finbook::model::file_format
