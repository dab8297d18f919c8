// Deform > Lip Sync… (issue 49): keys a mouth chart's drawings from a sound clip. The clip's
// phones are recognised off the GUI thread (PocketSphinx, US English; lipsync/speech_recognizer.h),
// constrained by the dialogue when it is typed, turned into mouth shapes by the animator's rules
// (lipsync/mouth_cues.h) and keyed on the mouth's layer from the clip's first frame
// (lipsync/lipsync_keys.h): one undo step. Without the speech models, the mouth follows the
// clip's loudness. Timings made by Papagayo, Moho or Rhubarb are imported the same way.
#pragma once

#include <finbook/model/lipsync/mouth_shape.h>
#include <finbook/model/types.h>

#include <QDialog>

#include <atomic>
#include <memory>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QThread;
class QTimer;

namespace finbook::model {
struct SoundClip;
}

namespace finbook::ui {

class EditorState;

class LipSyncDialog : public QDialog {
    Q_OBJECT
public:
    // `mouthId`: the swappable object to key (its set should be a mouth chart).
    LipSyncDialog(EditorState *state, model::Id mouthId, QWidget *parent = nullptr);
    ~LipSyncDialog() override;

    QComboBox *clips() const { return m_clips; }
    QPlainTextEdit *dialogue() const { return m_dialogue; }
    QPushButton *runButton() const { return m_run; }
    QPushButton *importButton() const { return m_import; }
    QProgressBar *progress() const { return m_progress; }
    QLabel *status() const { return m_status; }
    // Whether recognition is running.
    bool isRunning() const { return m_worker != nullptr; }
    // Keys the cues of the timings file `path` from the chosen clip's first frame (or frame 1
    // without a clip). False, with the reason shown, when the file does not read.
    bool importTimings(const QString &path);

    void run();
    void cancel();
    void done(int result) override;

    struct Job; // what the worker is given and gives back

signals:
    // A sentence for the status bar when the dialog closes after keying.
    void keyed(const QString &message);

private:
    void finished(const std::shared_ptr<Job> &job);
    bool key(const std::vector<model::lipsync::MouthCue> &cues, double seconds, qint64 start,
             const QString &how);
    // The clip picked in the Sound box (null when there is none), and its first tick.
    const model::SoundClip *currentClip() const;
    qint64 clipStart() const;
    void setBusy(bool busy);

    EditorState *m_state;
    model::Id m_mouthId;
    QComboBox *m_clips;
    QPlainTextEdit *m_dialogue;
    QLabel *m_engine;
    QLabel *m_status;
    QProgressBar *m_progress;
    QPushButton *m_run;
    QPushButton *m_import;
    QDialogButtonBox *m_buttons;
    QThread *m_worker = nullptr;
    QTimer *m_poll;
    std::shared_ptr<Job> m_job;
};

} // namespace finbook::ui
