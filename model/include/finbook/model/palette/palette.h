// The document's palette: named colour swatches the animator picks from (the Palette panel,
// the Brush toolbar's swatches), saved in the .finbook ("palt" section), as user palettes and
// as GIMP palette files (.gpl), which Krita, Inkscape, Pencil2D and GIMP read and write.
#pragma once

#include <finbook/geometry/expected.h>

#include <QByteArray>
#include <QColor>
#include <QString>
#include <QUndoCommand>

#include <vector>

namespace finbook::model {

class Document;

struct Swatch {
    QRgb color = 0xff000000; // opaque: a palette holds colours, not opacities
    QString name;
    friend bool operator==(const Swatch &, const Swatch &) = default;
};

struct Palette {
    QString name;
    std::vector<Swatch> swatches;
    friend bool operator==(const Palette &, const Palette &) = default;
};

// More than any palette people make (GIMP's largest bundled one has 256), few enough that a
// crafted file costs nothing.
constexpr int kMaxSwatches = 4096;
constexpr int kMaxSwatchNameChars = 256;

// A new document's palette: the ten colours the Brush toolbar always offered, named.
Palette defaultPalette();

// Names trimmed and cut to kMaxSwatchNameChars, colours made opaque, at most kMaxSwatches.
Palette sanitizedPalette(Palette palette);

// GIMP's palette format: "GIMP Palette", optional "Name:", "Columns:" and "Channels: RGBA"
// lines, '#' comments, then one "R G B [A] name" line per swatch (0..255). The error says
// what is wrong and on which line; a file that is not a palette is refused, not guessed at.
Expected<Palette, QString> readGpl(const QByteArray &bytes);
QByteArray writeGpl(const Palette &palette);

// The "palt" section's payload (finbook_file_format.h): u32 nameBytes utf8 u32 count
// (u32 color u32 nameBytes utf8)[count].
QByteArray paletteSectionPayload(const Palette &palette);
Expected<Palette, QString> readPaletteSection(const QByteArray &payload);

// One palette change (add, rename, recolour, reorder, delete, import): the whole palette
// before and after, so undo restores it exactly.
class SetPaletteCommand : public QUndoCommand {
public:
    SetPaletteCommand(Document *doc, Palette palette, const QString &text);
    void redo() override;
    void undo() override;

private:
    Document *m_doc;
    Palette m_new;
    Palette m_old;
};

} // namespace finbook::model
