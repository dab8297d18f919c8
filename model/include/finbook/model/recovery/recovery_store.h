// Recovery copies: the files autosave keeps of documents with unsaved changes, and how the
// next start finds the ones a crashed or killed Finbook left behind.
//
// A copy is an ordinary .finbook whose ancillary sections "rcvy" (a JSON description) and
// "thmb" (a PNG of the first frame) say what it is. Copies live in one folder named
// "<session>-<n>.finbook"; each running Finbook holds the lock "<session>.lock" there, so a
// copy is an orphan exactly when its session's lock is not held by a live process. Two
// running Finbooks therefore never list, take or delete each other's copies.
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/palette/palette.h>
#include <finbook/model/reference/reference.h>
#include <finbook/model/sound/sound_clip.h>
#include <finbook/model/types.h>

#include <QDateTime>
#include <QImage>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QLockFile;

namespace finbook::model {

// What a recovery copy says about itself.
struct RecoveryInfo {
    QString title;        // what the window called it: "walk.finbook", "Untitled"
    QString originalPath; // the file it was opened from or saved to; empty when untitled
    QDateTime savedAt;    // when the copy was taken (UTC)
    int frames = 0;
};

struct RecoveryCopy {
    QString path; // the copy itself
    RecoveryInfo info;
    QImage thumbnail; // the first frame, about 160 pixels wide; null if the copy has none
};

// The bytes of a recovery copy: the document (a snapshot; any thread) with its description and
// a thumbnail rendered here, the reference layer when there is one, the sound clips `sound`,
// the camera `camera`, the palette `palette` and the swap sets `swapSets`.
QByteArray recoveryCopyBytes(const std::vector<Layer> &layers, const DocumentSettings &settings,
                             const RecoveryInfo &info, const Reference &reference = {},
                             const std::vector<SoundClip> &sound = {},
                             const CameraTrack &camera = {},
                             const Palette &palette = defaultPalette(),
                             const std::vector<SwapSet> &swapSets = {});
// Copies larger than this are not listed (nor read): a recovery copy is an autosave of a
// drawing that had to fit in memory.
constexpr qint64 kMaxRecoveryCopyBytes = qint64(4) << 30;

// The description and thumbnail of the copy at `path`; nullopt when it is not one (or not
// readable). File → Open's rules: a regular file (not a link, a device or a pipe), at most
// kMaxRecoveryCopyBytes, a .finbook header; then only the two small sections describing the
// copy are read (a few reads, whatever the file's size), never the drawing.
std::optional<RecoveryCopy> readRecoveryCopy(const QString &path);

// $FINBOOK_RECOVERY_DIR when set, else "recovery" in the application's data folder.
QString recoveryFolder();

// This process's claim on its copies: a lock held from construction to destruction.
class RecoverySession {
public:
    explicit RecoverySession(const QString &folder = recoveryFolder());
    // Releases the lock. Copies not discarded stay, as after a crash, and become orphans.
    ~RecoverySession();
    RecoverySession(const RecoverySession &) = delete;
    RecoverySession &operator=(const RecoverySession &) = delete;

    // False when the folder or the lock could not be made (autosave is then off).
    bool isValid() const;
    QString folder() const { return m_folder; }
    QString id() const { return m_id; }
    // Where this session keeps the copy of its document number `document`.
    QString copyPath(int document) const;

    // Copies of Finbooks that are not running any more, newest first. (Looking removes the
    // dead sessions' stale locks.) Autosaver::adopt makes one this session's own.
    std::vector<RecoveryCopy> orphans() const;
    // Deletes an orphan the user does not want.
    bool discard(const RecoveryCopy &copy) const;

private:
    QString m_folder;
    QString m_id;
    std::unique_ptr<QLockFile> m_lock;
};

} // namespace finbook::model
