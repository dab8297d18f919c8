// Recovery copies on disk: their bytes, their description, the session locks.
#include "../reference/reference_section.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/recovery/recovery_store.h>
#include <finbook/model/render.h>
#include <finbook/model/scene/shot.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QRandomGenerator>
#include <QStandardPaths>

#include <algorithm>

namespace finbook::model {

namespace {
constexpr int kThumbnailWidth = 160;
// A folder holding thousands of copies (or of files named like them) is listed quickly: the
// newest this many are looked at, which is more than anyone picks from.
constexpr int kMaxCopiesLooked = 100;
const QString kCopySuffix = QStringLiteral(".finbook");
const QString kLockSuffix = QStringLiteral(".lock");

QByteArray thumbnailPng(const std::vector<Layer> &layers, const DocumentSettings &settings)
{
    const Frame first = composeShot(layers, 0);
    if (first.planes.empty() || settings.canvasSize.isEmpty())
        return {};
    const QSize size(kThumbnailWidth, std::max(1, kThumbnailWidth * settings.canvasSize.height() /
                                                      settings.canvasSize.width()));
    const QImage image = renderFrame(first, settings, size.boundedTo(QSize(160, 480)));
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return png;
}

// "<session>-<n>.finbook" → "<session>"; empty for any other name.
QString sessionOf(const QString &fileName)
{
    if (!fileName.endsWith(kCopySuffix))
        return {};
    const QString stem = fileName.chopped(kCopySuffix.size());
    const qsizetype dash = stem.lastIndexOf(QLatin1Char('-'));
    return dash > 0 ? stem.left(dash) : QString();
}

// A lock that only a dead owner makes stale (QLockFile's default also calls a 30-second-old
// lock stale, which would hand a running Finbook's copies to another).
std::unique_ptr<QLockFile> lockFor(const QString &path)
{
    auto lock = std::make_unique<QLockFile>(path);
    lock->setStaleLockTime(0);
    return lock;
}
} // namespace

QByteArray recoveryCopyBytes(const std::vector<Layer> &layers, const DocumentSettings &settings,
                             const RecoveryInfo &info, const Reference &reference,
                             const std::vector<SoundClip> &sound, const CameraTrack &camera,
                             const Palette &palette, const std::vector<SwapSet> &swapSets)
{
    const QJsonObject description{
        {QStringLiteral("title"), info.title},
        {QStringLiteral("original"), info.originalPath},
        {QStringLiteral("saved"), info.savedAt.toUTC().toString(Qt::ISODateWithMs)},
        {QStringLiteral("frames"), info.frames}};
    std::vector<AncillarySection> extra{
        {"rcvy", QJsonDocument(description).toJson(QJsonDocument::Compact)}};
    const QByteArray thumbnail = thumbnailPng(layers, settings);
    if (!thumbnail.isEmpty())
        extra.push_back({"thmb", thumbnail});
    if (!reference.isEmpty())
        for (AncillarySection &section : file_format::referenceSections(reference))
            extra.push_back(std::move(section));
    if (palette != defaultPalette())
        extra.push_back(paletteSection(palette));
    return serializeFinbook(layers, settings, extra, sound, camera, swapSets);
}

QString recoveryFolder()
{
    const QString overridden = qEnvironmentVariable("FINBOOK_RECOVERY_DIR");
    if (!overridden.isEmpty())
        return overridden;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("recovery"));
}

RecoverySession::RecoverySession(const QString &folder)
    : m_folder(folder)
{
    if (!QDir().mkpath(folder))
        return;
    for (int attempt = 0; attempt < 16 && !m_lock; ++attempt) {
        m_id = QStringLiteral("%1-%2")
                   .arg(QCoreApplication::applicationPid())
                   .arg(QRandomGenerator::global()->generate64() % 1000000007ull, 0, 36);
        auto lock = lockFor(QDir(folder).filePath(m_id + kLockSuffix));
        if (lock->tryLock(0))
            m_lock = std::move(lock);
    }
}

RecoverySession::~RecoverySession() = default; // the QLockFile removes its file

bool RecoverySession::isValid() const
{
    return m_lock != nullptr;
}

QString RecoverySession::copyPath(int document) const
{
    return QDir(m_folder).filePath(QStringLiteral("%1-%2").arg(m_id).arg(document) + kCopySuffix);
}

std::vector<RecoveryCopy> RecoverySession::orphans() const
{
    std::vector<RecoveryCopy> found;
    const QDir dir(m_folder);
    QStringList alive, dead;
    int looked = 0;
    // Newest first; links are not copies (readRecoveryCopy refuses them unopened anyway).
    for (const QString &name : dir.entryList({QStringLiteral("*") + kCopySuffix},
                                             QDir::Files | QDir::NoSymLinks, QDir::Time)) {
        const QString session = sessionOf(name);
        if (session.isEmpty() || session == m_id || alive.contains(session))
            continue;
        if (++looked > kMaxCopiesLooked)
            break;
        if (!dead.contains(session)) {
            // Taking the lock succeeds only when its owner is gone (or it never existed).
            auto probe = lockFor(dir.filePath(session + kLockSuffix));
            if (!probe->tryLock(0)) {
                alive << session;
                continue;
            }
            dead << session;
        }
        if (auto copy = readRecoveryCopy(dir.filePath(name)))
            found.push_back(std::move(*copy));
    }
    std::sort(found.begin(), found.end(), [](const RecoveryCopy &a, const RecoveryCopy &b) {
        return a.info.savedAt > b.info.savedAt;
    });
    return found;
}

bool RecoverySession::discard(const RecoveryCopy &copy) const
{
    return QFile::remove(copy.path) || !QFile::exists(copy.path);
}

} // namespace finbook::model
