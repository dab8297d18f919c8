// Shaded fills in `finbook-bench inflate` (issue 27): the GUI-thread cost of re-shading a
// posed frame, and a contact sheet of shaded drawings at rest and posed with a skeleton.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace finbook::bench {

// Opens `finbook` (a .finbook), takes its frame with the most posed objects, fills every
// enclosed region of each object that has no fill, shades every fill (three tones, rim),
// and times re-shading it: the tones of every fill recomputed for a new light (light the posed
// normals, cut the tone polygons; the posed mesh is cached per pose), then the frame painted;
// for a new pose of every object (pose the rest normals too); and after one object's pose
// changed (a drag), the others' tones cached. Each is timed `runs` times (median reported).
// With `savePosed`, the frame timed (posed, every fill shaded) is saved there as a .finbook.
QJsonObject reshadeCost(const QString &finbook, int runs = 15, const QString &savePosed = {});

// A contact sheet: each drawing (shared/data sketch JSON) filled, shaded in three tones with a
// rim, lit from the upper left, at rest and posed by its automatic skeleton (every bone bent).
// `cell` px a picture. One JSON object per drawing on stdout; false if the sheet cannot be
// written.
bool shadedSheet(const QStringList &files, const QString &out, int cell = 200);

} // namespace finbook::bench
