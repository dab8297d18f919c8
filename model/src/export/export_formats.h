// Internal: the writer of each kind of output, and what they share.
#pragma once

#include "../reference/reference_export.h"
#include "export_sound.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/frame_solids.h>

#include <QByteArray>
#include <QImage>
#include <QStringList>

#include <functional>
#include <initializer_list>

namespace finbook::model {

struct ExportContext {
    const ExportSource &source;
    const ExportOptions &options;
    const ExportPlan &plan;
    const ExportProgress &progress;
    const ExportReference &reference;
    const ExportSoundtrack &sound;

    // Reports progress; true when the caller asked to stop.
    bool cancelled(qint64 done, qint64 total) const { return progress && !progress(done, total); }
    const Frame &frame(std::size_t planIndex) const
    {
        return source.frames[std::size_t(plan.frames[planIndex])];
    }
    QImage render(std::size_t planIndex) const
    {
        return renderBand(planIndex, 0, plan.size.height());
    }
    // The camera for the entry, or null (the page as it is).
    const CameraState *camera(std::size_t planIndex) const
    {
        return planIndex < plan.cameras.size() ? &plan.cameras[planIndex] : nullptr;
    }
    QImage renderBand(std::size_t planIndex, int top, int rows) const
    {
        if (reference.isEmpty())
            return renderExportBand(frame(planIndex), source.settings, plan, top, rows, nullptr, {},
                                    camera(planIndex));
        return renderExportBand(frame(planIndex), source.settings, plan, top, rows,
                                &reference.reference(), reference.picture(plan.frames[planIndex]),
                                camera(planIndex));
    }
    // The frame as PNG bytes, rendered and compressed band by band: memory stays at one band
    // plus the compressed bytes whatever the picture's size. Empty when out of memory.
    QByteArray png(std::size_t planIndex) const;
};

using ExportOutcome = Expected<ExportResult, ExportError>;

ExportOutcome exportSequence(const ExportContext &context);
ExportOutcome exportEncoded(const ExportContext &context);
ExportOutcome exportFlipbook(const ExportContext &context);
ExportOutcome exportObj(const ExportContext &context);
ExportOutcome exportGlb(const ExportContext &context);
ExportOutcome exportLottie(const ExportContext &context); // Lottie JSON and dotLottie
// The Lottie JSON of the plan (export_lottie.cpp); empty when the export was cancelled.
QByteArray lottieJson(const ExportContext &context);

// The 3D formats' shared part (export_model.cpp): the plan's frame as solids, or why not (the
// export was cancelled, or the frame has nothing to inflate).
Expected<FrameSolids, ExportError> exportedSolids(const ExportContext &context);
// The sentence for ExportResult::note about the objects left out, empty when none were.
QString skippedSolidsNote(const ExportContext &context, const FrameSolids &solids);
// An ExportResult for a 3D model written to `files`.
ExportResult modelResult(const ExportContext &context, const QStringList &files,
                         const FrameSolids &solids);

// The files of a sequence in writing order: one image per tick (or one per drawing plus the
// exposure sheet, last). Names are made when asked for: a sequence may hold millions.
class SequenceFiles {
public:
    SequenceFiles(const ExportPlan &plan, const ExportOptions &options);
    qint64 count() const { return m_count; }
    QString name(qint64 index) const; // 0 <= index < count()
    // Whether `fileName` is one of name(0 .. count()-1), found without making them all.
    bool contains(const QString &fileName) const;
    // Whether `fileName` is named as this sequence's files are (its base name, "_", a number
    // of any width, its suffix), whether or not this export writes it.
    bool isSequenceName(const QString &fileName) const;

private:
    const ExportPlan &m_plan;
    const ExportOptions &m_options;
    qint64 m_count = 0;
    int m_digits = 4;
};
QString exposureSheetName(const ExportOptions &options);

// The file target as the system names it: options.target encoded, or its folder and
// options.nativeName.
QByteArray nativeTargetPath(const ExportOptions &options);
// Refuses a target that is a folder, or an existing file without options.overwrite.
std::optional<ExportError> checkFileTarget(const ExportOptions &options);
ExportError targetExists(const QString &path);
ExportError writeFailed(const QString &path, const QString &reason);
ExportError cancelledError();
ExportError targetBusy(const QString &path);

class FolderGuard;
class TargetLock;
// The start of a file export, once its target is checked: the target's folder made (by
// `guard`) and every lock taken, the leftovers of killed exports to them removed.
std::optional<ExportError> claimFileTarget(const QString &target, const FolderGuard &guard,
                                           std::initializer_list<TargetLock *> locks);

// A single-file export from start to end: the target checked and claimed (its folder made, the
// lock taken), `make` run for the file's bytes (or the error that stops the export), the bytes
// written beside the target, synced, and renamed into place. Nothing is left on failure.
std::optional<ExportError>
writeSingleFile(const ExportOptions &options,
                const std::function<Expected<QByteArray, ExportError>()> &make);

class PendingFile;
// Renames the finished file over the target: replacing it only with options.overwrite, so a
// file that appeared meanwhile (another program's export) is refused rather than replaced.
std::optional<ExportError> commitFile(PendingFile &pending, const ExportOptions &options);

// One frame as an SVG document: plan.size pixels, a viewBox in canvas units, each stroke one
// filled path (the union of tapered capsules between its samples).
QByteArray frameSvg(const Frame &frame, const DocumentSettings &settings, const ExportPlan &plan,
                    const CameraState *camera = nullptr);
// The self-contained HTML page for the drawings' PNG images (in plan order).
QByteArray flipbookHtml(const std::vector<QByteArray> &pngs, const ExportPlan &plan,
                        const QString &title, const QByteArray &soundWav = {});

} // namespace finbook::model
