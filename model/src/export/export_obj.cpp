// The 3D model export: one frame's objects inflated to closed solids (frame_solids.h), written
// as a Wavefront OBJ file with one object (and group) per drawing object and a material file
// beside it (NAME.mtl) holding each object's colour, as Blender imports them; a picture object's
// material names its picture, written beside them too (NAME_OBJECT.png). Both files go
// through the same safe path as the other single-file formats: locked, written beside the
// target, synced and renamed into place only when complete.
#include "export_formats.h"
#include "export_text.h"
#include "pending_output.h"
#include "target_lock.h"

#include <finbook/model/export/frame_solids.h>
#include <finbook/model/picture/picture_object.h>

#include <QColor>
#include <QFileInfo>

#include <algorithm>
#include <cerrno>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace finbook::model {

namespace {
// OBJ and MTL names end at white space for many readers: letters, digits, '-', '_' and '.'
// are kept (UTF-8), anything else becomes '_'. Repeated names get _2, _3, ...
std::vector<std::string> objectNames(const std::vector<ObjectSolid> &objects)
{
    std::vector<std::string> names;
    std::set<QString> used;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        QString name = objects[i].name.trimmed();
        for (QChar &c : name)
            if (!c.isLetterOrNumber() && c != QLatin1Char('-') && c != QLatin1Char('_') &&
                c != QLatin1Char('.'))
                c = QLatin1Char('_');
        if (name.isEmpty())
            name = QStringLiteral("object_%1").arg(i + 1);
        QString unique = name;
        for (int n = 2; used.count(unique); ++n)
            unique = QStringLiteral("%1_%2").arg(name).arg(n);
        used.insert(unique);
        names.push_back(unique.toStdString());
    }
    return names;
}

struct ObjFiles {
    QByteArray obj, mtl;
};

// A picture object's picture, written beside the OBJ for its material: NAME_OBJECT.png.
struct PictureFile {
    const PictureData *picture = nullptr;
    ExportOptions options; // its target (and bytes of it), as the OBJ's
};

// One file per picture the objects show (objects sharing a picture share its file), named
// after the OBJ and the first object showing it.
std::vector<PictureFile> pictureFiles(const FrameSolids &solids, const ExportOptions &options)
{
    const std::vector<std::string> names = objectNames(solids.objects);
    // The material file's name without its ".mtl": the OBJ's own text, its suffix dropped.
    const QString stem = objMaterialPath(options.target).chopped(4);
    QByteArray nativeStem = options.nativeName;
    if (const qsizetype dot = nativeStem.lastIndexOf('.'); dot > 0)
        nativeStem.truncate(dot);
    std::vector<PictureFile> files;
    for (std::size_t i = 0; i < solids.objects.size(); ++i) {
        const PictureData *picture = solids.objects[i].picture.get();
        if (!picture || std::any_of(files.begin(), files.end(),
                                    [&](const PictureFile &f) { return f.picture == picture; }))
            continue;
        PictureFile file{picture, options};
        const QString suffix = QStringLiteral("_%1.png").arg(QString::fromStdString(names[i]));
        file.options.target = stem + suffix;
        if (!options.nativeName.isEmpty())
            file.options.nativeName = nativeStem + suffix.toUtf8();
        files.push_back(std::move(file));
    }
    return files;
}

ObjFiles objFiles(const FrameSolids &solids, const QString &materialFile,
                  const std::vector<PictureFile> &pictures)
{
    const std::vector<std::string> names = objectNames(solids.objects);
    std::vector<geometry::ObjObject> objects;
    std::vector<geometry::MtlMaterial> materials;
    geometry::ObjMaterials links{QFileInfo(materialFile).fileName().toStdString(), names};
    for (std::size_t i = 0; i < solids.objects.size(); ++i) {
        const ObjectSolid &object = solids.objects[i];
        objects.push_back({names[i], object.solid});
        const QColor colour = QColor::fromRgba(object.color);
        materials.push_back(
            {names[i], colour.redF(), colour.greenF(), colour.blueF(), colour.alphaF(), {}});
        for (const PictureFile &file : pictures)
            if (file.picture == object.picture.get())
                materials.back().texture = QFileInfo(file.options.target).fileName().toStdString();
    }
    std::ostringstream obj, mtl;
    geometry::writeObj(obj, objects, links);
    geometry::writeMtl(mtl, materials);
    return {QByteArray::fromStdString(obj.str()), QByteArray::fromStdString(mtl.str())};
}

// The material file's options: its path (and bytes, when the target is named by bytes).
ExportOptions materialOptions(const ExportOptions &options)
{
    ExportOptions mtl = options;
    mtl.target = objMaterialPath(options.target);
    if (!options.nativeName.isEmpty()) {
        QByteArray name = options.nativeName;
        const qsizetype dot = name.lastIndexOf('.');
        if (dot > 0)
            name.truncate(dot);
        mtl.nativeName = name + ".mtl";
    }
    return mtl;
}

bool exists(const QByteArray &path)
{
    struct stat status {};
    return ::lstat(path.constData(), &status) == 0;
}

// The material file an export replaces, kept by a hidden hard link beside it until the OBJ is
// in place, so that a failed OBJ rename can put the old materials back (and a material file
// the export added can go again). Where the file system has no hard links the old file cannot
// be kept: restore() then only removes a file the export added.
class MaterialSetAside {
public:
    explicit MaterialSetAside(QByteArray path)
        : m_path(std::move(path))
        , m_existed(exists(m_path))
    {
        if (!m_existed)
            return;
        const qsizetype slash = m_path.lastIndexOf('/');
        const QByteArray folder = slash < 0 ? QByteArray(".") : m_path.left(slash);
        const QByteArray name = m_path.mid(slash + 1);
        for (int attempt = 0; attempt < 64 && m_kept.isEmpty(); ++attempt) {
            const QByteArray candidate = folder + "/.finbook-" + name + "-" +
                                         QByteArray::number(qint64(::getpid())) + "-" +
                                         QByteArray::number(attempt);
            if (::link(m_path.constData(), candidate.constData()) == 0)
                m_kept = candidate;
            else if (errno != EEXIST)
                break;
        }
    }
    ~MaterialSetAside()
    {
        if (!m_kept.isEmpty())
            ::unlink(m_kept.constData());
    }
    MaterialSetAside(const MaterialSetAside &) = delete;
    MaterialSetAside &operator=(const MaterialSetAside &) = delete;

    void restore()
    {
        if (!m_kept.isEmpty() && ::rename(m_kept.constData(), m_path.constData()) == 0)
            m_kept.clear();
        else if (!m_existed)
            ::unlink(m_path.constData());
    }

private:
    QByteArray m_path;
    bool m_existed;
    QByteArray m_kept;
};
} // namespace

ExportOutcome exportObj(const ExportContext &context)
{
    const ExportOptions &options = context.options;
    const ExportOptions mtlOptions = materialOptions(options);
    const QString target = options.target;
    if (QFileInfo(target).suffix().compare(QLatin1String("mtl"), Qt::CaseInsensitive) == 0)
        return unexpected(exportError(
            ExportErrorCode::BadOptions,
            Export::tr("\"%1\" would be overwritten by its own material file; give a file name "
                       "ending in .obj.")
                .arg(target)));
    for (const ExportOptions *file : {&options, &mtlOptions})
        if (auto error = checkFileTarget(*file))
            return unexpected(*error);
    FolderGuard guard(QFileInfo(target).path());
    TargetLock lock(target, false), mtlLock(mtlOptions.target, false);
    if (auto error = claimFileTarget(target, guard, {&lock, &mtlLock}))
        return unexpected(*error);

    const auto solids = exportedSolids(context);
    if (!solids)
        return unexpected(solids.error());
    const std::vector<PictureFile> pictures = pictureFiles(*solids, options);
    for (const PictureFile &picture : pictures)
        if (picture.options.target == target || picture.options.target == mtlOptions.target)
            return unexpected(targetExists(picture.options.target));
        else if (auto error = checkFileTarget(picture.options))
            return unexpected(*error);
    const ObjFiles files = objFiles(*solids, mtlOptions.target, pictures);

    PendingFile pendingObj(target), pendingMtl(mtlOptions.target);
    QString reason;
    if (!pendingObj.open(&reason) || !pendingMtl.open(&reason))
        return unexpected(writeFailed(target, reason));
    if (auto failed = writeSynced(pendingObj.file(), files.obj))
        return unexpected(writeFailed(target, *failed));
    if (auto failed = writeSynced(pendingMtl.file(), files.mtl))
        return unexpected(writeFailed(mtlOptions.target, *failed));
    // The pictures before the materials that name them, each complete before it is in place.
    QStringList written;
    for (const PictureFile &picture : pictures) {
        PendingFile pending(picture.options.target);
        if (!pending.open(&reason))
            return unexpected(writeFailed(picture.options.target, reason));
        if (auto failed = writeSynced(pending.file(), picture.picture->png))
            return unexpected(writeFailed(picture.options.target, *failed));
        if (auto error = commitFile(pending, picture.options))
            return unexpected(*error);
        written << picture.options.target;
    }
    // The materials first: an OBJ file in place always finds its colours. Should the OBJ
    // then fail, the material file is put back as it was (or goes again if this export added it).
    MaterialSetAside oldMaterials(nativeTargetPath(mtlOptions));
    if (auto error = commitFile(pendingMtl, mtlOptions))
        return unexpected(*error);
    if (auto error = commitFile(pendingObj, options)) {
        oldMaterials.restore();
        return unexpected(*error);
    }
    guard.keep();

    return modelResult(context, QStringList{target, mtlOptions.target} + written, *solids);
}

} // namespace finbook::model
