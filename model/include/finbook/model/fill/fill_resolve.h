// Which region each fill colours now, after whatever happened to the strokes since it was made.
//
// A fill keeps its colour on the face that holds its seed, provided that face is still bounded
// by at least one of the fill's strokes (a seed left behind by a moved outline must not colour
// whatever moved under it); failing that, on the face bounded by most of its strokes (at least
// half of them). A face cut in two by a new stroke keeps the colour on both halves: the faces
// that share one of the cutting strokes with the fill's face and are otherwise bounded only by
// the fill's strokes and the cutting ones inherit it. A region that has gone shows no colour;
// the fill stays in the object, so undoing the edit brings the colour back exactly. A later
// fill on the same face wins.
#pragma once

#include <finbook/model/fill/fill_regions.h>

#include <optional>

namespace finbook::model {

// For each face, the index of the fill it shows, or -1.
std::vector<int> faceFills(const ObjectRegions &regions, const std::vector<Fill> &fills);

// A fill of `face` in `color`: its seed, its bounding strokes (flat).
Fill fillOfFace(const ObjectRegions &regions, int face, QRgb color);

// The object's fills after the edits the Fill tool makes on `face`; nullopt when nothing would
// change. Filling a face that shows a fill recolours that fill (and ties it to the face as it is
// now); removing drops every fill that shows on the face. New fills are shaded as the object's
// last fill is.
std::optional<std::vector<Fill>>
fillsWithFace(const ObjectRegions &regions, const std::vector<Fill> &fills, int face, QRgb color);
std::optional<std::vector<Fill>> fillsWithoutFace(const ObjectRegions &regions,
                                                  const std::vector<Fill> &fills, int face);
// Every face that shows no fill gets one in `color` (shaded as the object's last fill).
std::optional<std::vector<Fill>> fillsWithAllFaces(const ObjectRegions &regions,
                                                   const std::vector<Fill> &fills, QRgb color);

// The fills of `group` once its pose has become its drawing (`baked`: its posed strokes, ids
// kept, as Apply Pose to Drawing makes them): each fill that shows moves its seed into the face
// of the baked drawing that lies where the fill is shown now, and each other face of the baked
// drawing (cut off by a limb passing over the body, a fold) gets a fill in the colour the pose
// shows there (its topmost fill as painted, paintLayers: a cut-out's layers and sockets).
std::vector<Fill> fillsAfterBake(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap);

// The face under canvas point p as the object shows now (posed where it is posed), or -1.
int displayedFaceAt(const ObjectRegions &regions, const StrokeGroup &group, QPointF p);

} // namespace finbook::model
