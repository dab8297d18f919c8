#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/ui/inbetween/between_fit_view.h>
#include <finbook/ui/inbetween/inbetween_dialog.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QShortcut>
#include <QSlider>
#include <QSpinBox>
#include <QThread>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace finbook::ui {

namespace {
constexpr int kDefaultCount = 3;
constexpr int kFavourSteps = 100; // the slider's -100..100 is favour -1..1

// One change of one object's correspondence pins, undone inside the dialog.
class PinsCommand : public QUndoCommand {
public:
    PinsCommand(InbetweenDialog *dialog, int index, std::vector<model::BetweenPin> before,
                std::vector<model::BetweenPin> after)
        : m_dialog(dialog)
        , m_index(index)
        , m_before(std::move(before))
        , m_after(std::move(after))
    {
        setText(InbetweenDialog::tr("Move Correspondence Pins"));
    }
    void redo() override { m_dialog->applyPins(m_index, m_after); }
    void undo() override { m_dialog->applyPins(m_index, m_before); }

private:
    InbetweenDialog *m_dialog;
    int m_index;
    std::vector<model::BetweenPin> m_before, m_after;
};
} // namespace

InbetweenDialog::InbetweenDialog(model::Document *document, model::Id firstKey, model::Id secondKey,
                                 const deform::ArapOptions &options, PreviewSink preview,
                                 QWidget *parent)
    : QDialog(parent)
    , m_doc(document)
    , m_first(firstKey)
    , m_second(secondKey)
    , m_arap(options)
    , m_sink(std::move(preview))
{
    if (m_doc->frameIndex(m_first) > m_doc->frameIndex(m_second))
        std::swap(m_first, m_second);
    setWindowTitle(tr("Generate In-betweens"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildControls());
    m_objects = new QListWidget(this);
    m_objects->setObjectName(QStringLiteral("inbetweenObjects"));
    m_objects->setSelectionMode(QAbstractItemView::NoSelection);
    // A fit that failed says why and where in a sentence or two: wrapped, not cut off.
    m_objects->setWordWrap(true);
    m_objects->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_objects->setResizeMode(QListView::Adjust);
    layout->addWidget(new QLabel(tr("Objects:"), this));
    layout->addWidget(m_objects);
    // The fit of a drawing carried onto another, with its correspondence pins.
    m_fitLabel = new QLabel(tr("Where the first drawing lands on the second (drag to pin):"), this);
    m_fitLabel->setWordWrap(true);
    layout->addWidget(m_fitLabel);
    m_fitObject = new QComboBox(this);
    m_fitObject->setObjectName(QStringLiteral("inbetweenFitObject"));
    layout->addWidget(m_fitObject);
    m_fitView = new BetweenFitView(this);
    m_fitView->setObjectName(QStringLiteral("inbetweenFitView"));
    layout->addWidget(m_fitView, 1);
    m_fitLabel->hide();
    m_fitObject->hide();
    m_fitView->hide();
    m_pinUndo = new QUndoStack(this);
    connect(new QShortcut(QKeySequence::Undo, this), &QShortcut::activated, m_pinUndo,
            &QUndoStack::undo);
    connect(new QShortcut(QKeySequence::Redo, this), &QShortcut::activated, m_pinUndo,
            &QUndoStack::redo);
    connect(m_fitView, &BetweenFitView::pinsDragged, this,
            [this](const std::vector<model::BetweenPin> &pins) { requestRefit(m_shownFit, pins); });
    connect(m_fitView, &BetweenFitView::pinsChanged, this,
            [this](const std::vector<model::BetweenPin> &before,
                   const std::vector<model::BetweenPin> &after) {
                m_pinUndo->push(new PinsCommand(this, m_shownFit, before, after));
            });
    connect(m_fitObject, &QComboBox::currentIndexChanged, this,
            [this](int) { showFitOf(m_fitObject->currentData().toInt()); });
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("inbetweenStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    startFitting();
    updatePlan();
}

// What the fitter fits: copies of the keys, so it never touches the document.
void InbetweenDialog::startFitting()
{
    const model::Frame *first = m_doc->frame(m_first);
    const model::Frame *second = m_doc->frame(m_second);
    if (!first || !second || m_first == m_second ||
        model::differentDrawings(*first, *second).empty()) {
        m_between->setVisible(false);
        return;
    }
    auto keys = std::make_shared<std::pair<model::Frame, model::Frame>>(*first, *second);
    auto result = std::make_shared<model::KeyFits>();
    const double closeGap = m_doc->settings().closeGap;
    m_fitter = QThread::create([keys, result, closeGap] {
        *result = model::fitKeyDrawings(keys->first, keys->second, closeGap);
    });
    m_fitter->setParent(this);
    m_ok->setEnabled(false);
    connect(m_fitter, &QThread::finished, this, [this, result] {
        m_fitter->deleteLater();
        m_fitter = nullptr;
        m_fits = std::move(*result);
        m_ok->setEnabled(true);
        const model::Frame *key = m_doc->frame(m_first);
        for (std::size_t i = 0; i < m_fits.fits.size(); ++i)
            if (m_fits.fits[i] && key && i < key->groups.size())
                m_fitObject->addItem(
                    key->groups[i].name.isEmpty() ? tr("(unnamed)") : key->groups[i].name, int(i));
        if (m_fitObject->count() > 0) {
            m_fitLabel->show();
            m_fitObject->setVisible(m_fitObject->count() > 1);
            m_fitView->show();
            showFitOf(m_fitObject->itemData(0).toInt());
        }
        updatePlan();
    });
    m_fitter->start();
}

void InbetweenDialog::showFitOf(int index)
{
    if (index < 0 || std::size_t(index) >= m_fits.fits.size() || !m_fits.fits[std::size_t(index)])
        return;
    m_shownFit = index;
    m_fitView->setFit(m_fits.fits[std::size_t(index)]);
}

void InbetweenDialog::applyPins(int index, const std::vector<model::BetweenPin> &pins)
{
    if (index == m_shownFit)
        m_fitView->setPins(pins);
    requestRefit(index, pins);
}

void InbetweenDialog::requestRefit(int index, std::vector<model::BetweenPin> pins)
{
    if (index < 0 || std::size_t(index) >= m_fits.fits.size() || !m_fits.fits[std::size_t(index)])
        return;
    if (m_refitter) { // the newest pins are fitted when this refit is done
        m_pendingRefit = std::make_pair(index, std::move(pins));
        return;
    }
    const std::shared_ptr<const model::DrawingFit> previous = m_fits.fits[std::size_t(index)];
    auto result = std::make_shared<
        std::optional<Expected<std::shared_ptr<const model::DrawingFit>, QString>>>();
    m_refitter = QThread::create(
        [previous, pins, result] { *result = model::refitDrawings(*previous, pins); });
    m_refitter->setParent(this);
    m_ok->setEnabled(false);
    m_status->setText(tr("Fitting the drawings that differ…"));
    connect(m_refitter, &QThread::finished, this, [this, index, result] {
        m_refitter->deleteLater();
        m_refitter = nullptr;
        if (*result && **result) {
            m_fits.fits[std::size_t(index)] = ***result;
            if (index == m_shownFit)
                m_fitView->setFit(***result);
        }
        if (m_pendingRefit) {
            auto [next, newest] = std::move(*m_pendingRefit);
            m_pendingRefit.reset();
            requestRefit(next, std::move(newest));
            return;
        }
        m_ok->setEnabled(true);
        updatePlan();
        if (*result && !**result)
            m_status->setText(
                tr("With these pins the drawings could not be fitted: %1").arg((*result)->error()));
    });
    m_refitter->start();
}

model::DrawingFits InbetweenDialog::fits() const
{
    return !m_between->isHidden() && m_between->isChecked() ? m_fits.fits : model::DrawingFits{};
}

// What the worker poses: copies only, so it never touches the dialog or the document.
struct InbetweenDialog::PreviewJob {
    // The middle in-between is planned here too: a drawing carried onto another costs its
    // Apply Pose (tens of milliseconds, up to half a second on a dense one).
    model::Frame first, second;
    double middle = 0.5;
    model::TargetPath path = model::TargetPath::Arc;
    model::DrawingFits fits;
    std::vector<model::Frame> frames;
    model::DeformSetupCache setups;
    deform::ArapOptions options;
    double closeGap = -1.0;
    int interpolated = 0;
    std::optional<Expected<int, QString>> solved;
};

InbetweenDialog::~InbetweenDialog()
{
    if (m_worker)
        m_worker->wait(); // a QThread must not be destroyed while it runs (one pose at most)
    if (m_fitter)
        m_fitter->wait(); // one fit per object that differs: a second or so at most
    if (m_refitter)
        m_refitter->wait(); // one refit: tens of milliseconds
    if (m_planner)
        m_planner->wait(); // the in-betweens being made
}

QWidget *InbetweenDialog::buildControls()
{
    auto *box = new QWidget(this);
    auto *form = new QFormLayout(box);
    form->setContentsMargins(0, 0, 0, 0);
    m_count = new QSpinBox(box);
    m_count->setObjectName(QStringLiteral("inbetweenCount"));
    m_count->setRange(1, model::InsertInbetweensCommand::kMaxInbetweens);
    m_count->setValue(kDefaultCount);
    form->addRow(tr("&Frames between the keys:"), m_count);
    m_spacing = new QComboBox(box);
    m_spacing->setObjectName(QStringLiteral("inbetweenSpacing"));
    m_spacing->addItem(tr("Linear"), int(model::SpacingKind::Linear));
    m_spacing->addItem(tr("Ease in (slow from the first key)"), int(model::SpacingKind::EaseIn));
    m_spacing->addItem(tr("Ease out (slow into the second key)"), int(model::SpacingKind::EaseOut));
    m_spacing->addItem(tr("Ease in and out"), int(model::SpacingKind::EaseInOut));
    m_spacing->addItem(tr("Favour…"), int(model::SpacingKind::Favour));
    form->addRow(tr("&Spacing:"), m_spacing);
    m_favour = new QSlider(Qt::Horizontal, box);
    m_favour->setObjectName(QStringLiteral("inbetweenFavour"));
    m_favour->setRange(-kFavourSteps, kFavourSteps);
    m_favour->setToolTip(tr("Left favours the first key, right the second."));
    form->addRow(tr("F&avour:"), m_favour);
    // Shown only with Favour chosen: a disabled slider still looks like one to drag.
    form->setRowVisible(m_favour, false);
    m_arcs = new QCheckBox(tr("Move pins and cage corners along &arcs"), box);
    m_arcs->setObjectName(QStringLiteral("inbetweenArcs"));
    m_arcs->setChecked(true);
    m_arcs->setToolTip(tr("A limb swung between the keys keeps its length. Unchecked, every "
                          "target moves in a straight line."));
    form->addRow(m_arcs);
    m_between = new QCheckBox(tr("Carry &different drawings onto each other"), box);
    m_between->setObjectName(QStringLiteral("inbetweenBetweenDrawings"));
    m_between->setChecked(true);
    m_between->setToolTip(
        tr("Where the two keys are separate drawings of an object, the first is fitted onto "
           "the second as rigidly as possible and carried there, fading into the second's "
           "lines at the end. Unchecked, the drawing switches over half way."));
    form->addRow(m_between);
    connect(m_between, &QCheckBox::toggled, this, &InbetweenDialog::updatePlan);
    connect(m_count, &QSpinBox::valueChanged, this, &InbetweenDialog::updatePlan);
    connect(m_spacing, &QComboBox::currentIndexChanged, this, [this, form] {
        form->setRowVisible(m_favour, options().spacing.kind == model::SpacingKind::Favour);
        updatePlan();
    });
    connect(m_favour, &QSlider::valueChanged, this, &InbetweenDialog::updatePlan);
    connect(m_arcs, &QCheckBox::toggled, this, &InbetweenDialog::updatePlan);
    return box;
}

int InbetweenDialog::count() const
{
    return m_count->value();
}

model::InbetweenOptions InbetweenDialog::options() const
{
    model::InbetweenOptions o;
    o.spacing.kind = model::SpacingKind(m_spacing->currentData().toInt());
    o.spacing.favour = double(m_favour->value()) / kFavourSteps;
    o.path = m_arcs->isChecked() ? model::TargetPath::Arc : model::TargetPath::Straight;
    return o;
}

QString InbetweenDialog::describe(const model::InbetweenObjectReport &object) const
{
    const QString name = object.name.isEmpty() ? tr("(unnamed)") : object.name;
    switch (object.fate) {
    case model::ObjectFate::Interpolated:
        return tr("%1: interpolated").arg(name);
    case model::ObjectFate::HeldNoRig:
        return tr("%1: held from the first key (no pins, cage or skeleton)").arg(name);
    case model::ObjectFate::HeldRigDiffers:
        return tr("%1: held from the first key (its pins, cage or skeleton differ between the "
                  "keys)")
            .arg(name);
    case model::ObjectFate::FirstKeyOnly:
        return tr("%1: only in the first key, held in the first half").arg(name);
    case model::ObjectFate::SecondKeyOnly:
        return tr("%1: only in the second key, held in the second half").arg(name);
    case model::ObjectFate::Fitted:
        return tr("%1: carried from the first key's drawing to the second's").arg(name);
    }
    return name;
}

void InbetweenDialog::updatePlan()
{
    const model::Frame *first = m_doc->frame(m_first);
    const model::Frame *second = m_doc->frame(m_second);
    if (!first || !second || m_first == m_second) {
        m_status->setText(tr("Select two different frames as keys."));
        return;
    }
    const model::InbetweenOptions o = options();
    const std::vector<double> times = model::inbetweenTimes(count(), o.spacing);
    const double middle = times[(times.size() - 1) / 2];
    // What becomes of each object (no frame planned: cheap); the frame is planned by the worker.
    const model::InbetweenPlan plan = model::planInbetweens(*first, *second, {}, o.path, fits());
    m_objects->clear();
    const bool carrying = !m_between->isHidden() && m_between->isChecked();
    const auto refused = [&](int index) {
        return carrying &&
               std::any_of(m_fits.failures.begin(), m_fits.failures.end(),
                           [index](const auto &failure) { return failure.first == index; });
    };
    for (const model::InbetweenObjectReport &object : plan.objects) {
        // A drawing that could not be carried is held in each half, as an object in one key
        // only; its own line below says so once, and why.
        if ((object.fate == model::ObjectFate::FirstKeyOnly && refused(object.firstIndex)) ||
            (object.fate == model::ObjectFate::SecondKeyOnly && refused(object.secondIndex)))
            continue;
        m_objects->addItem(describe(object));
    }
    if (carrying)
        for (const auto &[index, why] : m_fits.failures)
            m_objects->addItem(tr("%1: could not be carried onto the second key's drawing, so it "
                                  "switches over half way. %2")
                                   .arg(first->groups[std::size_t(index)].name.isEmpty()
                                            ? tr("(unnamed)")
                                            : first->groups[std::size_t(index)].name,
                                        why));
    m_status->setText(fitting() ? tr("Fitting the drawings that differ…")
                                : tr("Posing the preview…"));
    if (m_worker) { // the running pose is out of date: pose again when it is done
        m_replan = true;
        return;
    }
    auto job = std::make_shared<PreviewJob>();
    job->interpolated = plan.interpolatedCount();
    job->first = *first;
    job->second = *second;
    job->middle = middle;
    job->path = o.path;
    job->fits = fits();
    job->setups = m_setups;
    job->options = m_arap;
    job->closeGap = m_doc->settings().closeGap;
    m_worker = QThread::create([job] {
        job->frames =
            model::planInbetweens(job->first, job->second, {job->middle}, job->path, job->fits)
                .frames;
        job->solved =
            model::solveInbetweenPoses(job->frames, job->options, &job->setups, job->closeGap);
    });
    m_worker->setParent(this);
    connect(m_worker, &QThread::finished, this, [this, job] {
        m_worker->deleteLater();
        m_worker = nullptr;
        m_setups = std::move(job->setups); // keeps the factorizations for the next pose
        if (m_replan) {
            m_replan = false;
            updatePlan();
            return;
        }
        showPreview(*job);
    });
    m_worker->start();
}

void InbetweenDialog::showPreview(PreviewJob &job)
{
    if (!job.solved || !*job.solved) {
        m_preview.reset();
        m_status->setText(tr("The preview could not be posed: %1")
                              .arg(job.solved ? job.solved->error() : QString()));
    } else {
        m_preview = std::move(job.frames.front());
        m_status->setText(fitting() ? tr("Fitting the drawings that differ…")
                          : job.interpolated == 0 && fits().empty()
                              ? tr("No object has matching pins or a matching cage in both "
                                   "keys: the in-betweens will only hold drawings.")
                              : tr("The canvas shows the middle in-between."));
    }
    if (m_sink)
        m_sink(m_preview);
}

void InbetweenDialog::accept()
{
    // Frames carried from one drawing onto another are made off the GUI thread, then OK
    // closes the dialog with them.
    const model::DrawingFits carried = fits();
    const model::Frame *first = m_doc->frame(m_first);
    const model::Frame *second = m_doc->frame(m_second);
    if (m_planned || m_planner || carried.empty() || !first || !second) {
        if (!m_planner)
            QDialog::accept();
        return;
    }
    const model::InbetweenOptions o = options();
    auto keys = std::make_shared<std::pair<model::Frame, model::Frame>>(*first, *second);
    auto plan = std::make_shared<model::InbetweenPlan>();
    const std::vector<double> times = model::inbetweenTimes(count(), o.spacing);
    m_planner = QThread::create([keys, plan, times, path = o.path, carried] {
        *plan = model::planInbetweens(keys->first, keys->second, times, path, carried);
    });
    m_planner->setParent(this);
    m_ok->setEnabled(false);
    m_status->setText(tr("Making the in-betweens…"));
    connect(m_planner, &QThread::finished, this, [this, plan] {
        m_planner->deleteLater();
        m_planner = nullptr;
        m_planned = std::move(*plan);
        QDialog::accept();
    });
    m_planner->start();
}

void InbetweenDialog::done(int result)
{
    if (m_worker) // a pose still running must not bring the preview back
        m_worker->disconnect(this);
    if (m_fitter)
        m_fitter->disconnect(this);
    if (m_refitter)
        m_refitter->disconnect(this);
    if (m_planner && result != QDialog::Accepted)
        m_planner->disconnect(this);
    if (m_sink)
        m_sink(std::nullopt); // the preview never outlives the dialog
    QDialog::done(result);
}

} // namespace finbook::ui
