#include <finbook/model/lipsync/lipsync_import.h>
#include <finbook/model/lipsync/lipsync_keys.h>
#include <finbook/model/lipsync/mouth_cues.h>
#include <finbook/model/lipsync/speech_recognizer.h>
#include <finbook/model/sound/sound_decode.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/lipsync/lip_sync_dialog.h>
#include <finbook/ui/window/editor_state.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace finbook::ui {

namespace lipsync = model::lipsync;

// What the worker is given and gives back; the GUI thread reads `progress` while it runs.
struct LipSyncDialog::Job {
    QByteArray bytes; // the clip's file
    QString dialogue;
    double fps = 12;
    std::atomic<double> progress{0.0};
    std::atomic<bool> cancelled{false};
    // Results
    QString error;
    bool canceled = false;
    bool loudnessOnly = false;
    double seconds = 0;
    std::vector<lipsync::MouthCue> cues;
    QStringList unknownWords;
};

namespace {
bool modelsInstalled()
{
    const QDir dir(lipsync::speechModelDir());
    return dir.exists(QStringLiteral("cmudict-en-us.dict")) && dir.exists(QStringLiteral("en-us"));
}

// Decodes the clip and finds its mouth cues: recognised phones by the rules, or the loudness.
void runJob(LipSyncDialog::Job &job);
} // namespace

LipSyncDialog::LipSyncDialog(EditorState *state, model::Id mouthId, QWidget *parent)
    : QDialog(parent)
    , m_state(state)
    , m_mouthId(mouthId)
    , m_clips(new QComboBox(this))
    , m_dialogue(new QPlainTextEdit(this))
    , m_engine(new QLabel(this))
    , m_status(new QLabel(this))
    , m_progress(new QProgressBar(this))
    , m_run(new QPushButton(tr("&Run"), this))
    , m_import(new QPushButton(tr("&Import Timings..."), this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Close, this))
    , m_poll(new QTimer(this))
{
    setObjectName(QStringLiteral("lipSyncDialog"));
    setWindowTitle(tr("Lip Sync"));
    m_clips->setObjectName(QStringLiteral("lipSync.clip"));
    m_dialogue->setObjectName(QStringLiteral("lipSync.dialogue"));
    m_dialogue->setPlaceholderText(tr("Optional: the words spoken, for a closer fit"));
    m_dialogue->setTabChangesFocus(true);
    m_dialogue->setMaximumHeight(90);
    m_status->setObjectName(QStringLiteral("lipSync.status"));
    m_status->setWordWrap(true);
    m_engine->setWordWrap(true);
    m_progress->setObjectName(QStringLiteral("lipSync.progress"));
    m_progress->setRange(0, 100);
    m_progress->hide();
    m_run->setObjectName(QStringLiteral("lipSync.run"));
    m_import->setObjectName(QStringLiteral("lipSync.import"));
    m_run->setDefault(true);

    model::Document *doc = m_state->document();
    const model::StrokeGroup *mouth = doc->group(mouthId);
    const model::SwapSet *set = mouth ? doc->swapSet(mouth->swap.set) : nullptr;
    for (const model::SoundClip &clip : doc->soundtrack().clips())
        m_clips->addItem(tr("%1 (from frame %2)").arg(clip.name).arg(clip.start + 1),
                         QVariant::fromValue(quint64(clip.id)));
    m_engine->setText(
        modelsInstalled()
            ? tr("Recognises English speech (PocketSphinx, US English). Other languages: "
                 "import timings made elsewhere.")
            : tr("The speech models are not installed (Debian: pocketsphinx-en-us): the mouth "
                 "follows the loudness only, closed, half open or open."));

    auto *form = new QFormLayout;
    form->addRow(tr("Mouth:"),
                 new QLabel(set ? tr("%1 (%2 drawings)").arg(set->name).arg(set->drawings.size())
                                : tr("(none)"),
                            this));
    form->addRow(tr("&Sound:"), m_clips);
    form->addRow(tr("&Dialogue:"), m_dialogue);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_engine);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    m_buttons->addButton(m_run, QDialogButtonBox::ActionRole);
    m_buttons->addButton(m_import, QDialogButtonBox::ActionRole);
    layout->addWidget(m_buttons);

    if (m_clips->count() == 0) {
        m_run->setEnabled(false);
        m_status->setText(tr("The animation has no sound: File > Import Sound… first, or import "
                             "timings made elsewhere."));
    }
    connect(m_run, &QPushButton::clicked, this, &LipSyncDialog::run);
    connect(m_import, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import Lip Sync Timings"),
                                                          QString(), lipsync::lipSyncFileFilter());
        if (!path.isEmpty())
            importTimings(path);
    });
    connect(m_buttons, &QDialogButtonBox::rejected, this, [this] {
        if (isRunning())
            cancel();
        else
            reject();
    });
    m_poll->setInterval(50);
    connect(m_poll, &QTimer::timeout, this, [this] {
        if (m_job)
            m_progress->setValue(int(std::lround(100.0 * m_job->progress.load())));
    });
}

LipSyncDialog::~LipSyncDialog()
{
    if (m_worker) {
        m_job->cancelled = true;
        m_worker->disconnect(this);
        m_worker->wait();
    }
}

const model::SoundClip *LipSyncDialog::currentClip() const
{
    const model::Id id = model::Id(m_clips->currentData().toULongLong());
    for (const model::SoundClip &clip : m_state->document()->soundtrack().clips())
        if (clip.id == id)
            return &clip;
    return nullptr;
}

qint64 LipSyncDialog::clipStart() const
{
    const model::SoundClip *clip = currentClip();
    return clip ? clip->start : 0;
}

void LipSyncDialog::setBusy(bool busy)
{
    m_progress->setVisible(busy);
    m_progress->setValue(0);
    m_run->setEnabled(!busy);
    m_import->setEnabled(!busy);
    m_clips->setEnabled(!busy);
    m_dialogue->setReadOnly(busy);
    m_buttons->button(QDialogButtonBox::Close)->setText(busy ? tr("Cancel") : tr("Close"));
    if (busy)
        m_poll->start();
    else
        m_poll->stop();
}

void LipSyncDialog::run()
{
    if (m_worker)
        return;
    const model::SoundClip *clip = currentClip();
    if (!clip)
        return;
    m_job = std::make_shared<Job>();
    m_job->bytes = clip->bytes; // implicitly shared: no copy
    m_job->dialogue = m_dialogue->toPlainText();
    m_job->fps = m_state->document()->settings().fps;
    m_status->setText(tr("Listening…"));
    setBusy(true);
    std::shared_ptr<Job> job = m_job;
    m_worker = QThread::create([job] { runJob(*job); });
    m_worker->setParent(this);
    connect(m_worker, &QThread::finished, this, [this, job] {
        m_worker->deleteLater();
        m_worker = nullptr;
        setBusy(false);
        finished(job);
    });
    m_worker->start(QThread::LowPriority);
}

void LipSyncDialog::cancel()
{
    if (m_job)
        m_job->cancelled = true;
    m_status->setText(tr("Cancelling…"));
}

void LipSyncDialog::finished(const std::shared_ptr<Job> &job)
{
    if (job->canceled) {
        m_status->setText(tr("Cancelled: nothing was changed."));
        return;
    }
    if (!job->error.isEmpty()) {
        m_status->setText(job->error + QLatin1Char(' ') + tr("Nothing was changed."));
        return;
    }
    QString how = job->loudnessOnly ? tr("from the loudness (the speech models are not installed)")
                  : job->dialogue.trimmed().isEmpty() ? tr("from the recognised speech")
                                                      : tr("from the speech and the dialogue");
    if (!job->unknownWords.isEmpty())
        how += QLatin1String("; ") + tr("spelt by rules, not found in the dictionary: %1")
                                         .arg(job->unknownWords.join(QLatin1String(", ")));
    key(job->cues, job->seconds, clipStart(), how);
}

bool LipSyncDialog::key(const std::vector<lipsync::MouthCue> &cues, double seconds, qint64 start,
                        const QString &how)
{
    model::Document *doc = m_state->document();
    const double fps = doc->settings().fps;
    const int frames = std::max(1, int(std::ceil(seconds * fps - 1e-9)));
    const auto shapes = lipsync::mouthShapesPerFrame(cues, fps, frames);
    const lipsync::LipSyncResult r =
        lipsync::keyMouth(doc, m_mouthId, start, shapes, tr("Lip Sync"));
    if (!r.error.isEmpty()) {
        m_status->setText(r.error);
        return false;
    }
    QString message = tr("Keyed the mouth on %n frame(s), %1.", nullptr, r.keyed).arg(how);
    if (r.withoutMouth > 0)
        message += QLatin1Char(' ') + tr("%n frame(s) of the mouth's layer hold no mouth and were "
                                         "left as they were.",
                                         nullptr, r.withoutMouth);
    m_status->setText(message);
    emit keyed(message);
    return true;
}

bool LipSyncDialog::importTimings(const QString &path)
{
    const double fps = m_state->document()->settings().fps;
    const lipsync::MouthCueImport imported = lipsync::importMouthCues(path, fps);
    if (!imported.ok()) {
        m_status->setText(
            tr("%1 was not imported: %2").arg(QFileInfo(path).fileName(), imported.error));
        return false;
    }
    // The timings end with their last cue: it is held one frame.
    const double seconds = imported.cues.back().start + 1.0 / fps;
    return key(imported.cues, seconds, m_clips->count() > 0 ? clipStart() : 0,
               tr("from %1").arg(QFileInfo(path).fileName()));
}

void LipSyncDialog::done(int result)
{
    if (m_worker) { // closing while it listens cancels; the dialog stays to say so
        cancel();
        return;
    }
    QDialog::done(result);
}

namespace {
void runJob(LipSyncDialog::Job &job)
{
    const auto decoded = model::decodeSound(job.bytes, &job.cancelled);
    if (job.cancelled) {
        job.canceled = true;
        return;
    }
    if (!decoded) {
        job.error = decoded.error();
        return;
    }
    lipsync::SpeechAudio audio;
    audio.sampleRate = model::kSoundRate;
    audio.samples.resize(std::size_t(decoded->frames()));
    for (std::size_t i = 0; i < audio.samples.size(); ++i)
        audio.samples[i] = 0.5f * model::DecodedSound::kScale *
                           (float(decoded->samples[2 * i]) + float(decoded->samples[2 * i + 1]));
    job.seconds = decoded->seconds();
    const auto recognized = lipsync::recognizePhones(audio, job.dialogue, [&job](double done) {
        job.progress = done;
        return !job.cancelled.load();
    });
    if (recognized) {
        job.cues = lipsync::mouthCuesFromPhones(recognized->phones, job.fps);
        job.unknownWords = recognized->unknownWords;
        return;
    }
    switch (recognized.error().kind) {
    case lipsync::SpeechErrorKind::Canceled:
        job.canceled = true;
        return;
    case lipsync::SpeechErrorKind::ModelMissing:
        job.loudnessOnly = true;
        job.cues = lipsync::loudnessCues(audio, job.fps);
        if (job.cues.empty())
            job.error = QCoreApplication::translate("finbook::ui::LipSyncDialog",
                                                    "The clip holds no sound to follow.");
        return;
    default:
        job.error = recognized.error().message;
    }
}
} // namespace

} // namespace finbook::ui
