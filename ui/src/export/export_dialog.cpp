// ExportDialog: the form. Running the export is in export_dialog_run.cpp.
#include <finbook/model/document.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/export/export_job.h>
#include <finbook/ui/widgets/color_button.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
using model::ExportFormat;

// The target without the suffix of any export format: switching formats keeps the name.
QString stem(const QString &path)
{
    const QFileInfo info(path);
    if (model::exportFormatForPath(path) && !info.isDir())
        return QDir(info.path()).filePath(info.completeBaseName());
    return path;
}

QString withFormat(const QString &stemPath, ExportFormat format)
{
    if (model::exportsSequence(format))
        return stemPath;
    return stemPath + QLatin1Char('.') + model::exportFormatSuffix(format);
}
} // namespace

ExportDialog::ExportDialog(const model::Document &document, const QString &documentPath,
                           QWidget *parent)
    : QDialog(parent)
    , m_doc(document)
    , m_documentPath(documentPath)
{
    setWindowTitle(tr("Export Animation"));
    buildForm();
    const model::DocumentSettings &s = m_doc.settings();
    m_fps->setValue(s.fps);
    m_loop->setChecked(s.loop);
    m_colour->setColor(QColor::fromRgb(s.background));
    const QFileInfo info(documentPath);
    const QString folder = documentPath.isEmpty() ? QDir::homePath() : info.path();
    const QString name = documentPath.isEmpty() ? tr("untitled") : info.completeBaseName();
    setFormat(ExportFormat::Gif);
    setTarget(withFormat(QDir(folder).filePath(name), ExportFormat::Gif));
    updateFields();
}

ExportDialog::~ExportDialog() = default;

void ExportDialog::buildForm()
{
    m_format = new QComboBox(this);
    const std::pair<ExportFormat, QString> formats[] = {
        {ExportFormat::Gif, tr("Animated GIF")},
        {ExportFormat::Mp4, tr("MP4 video (H.264)")},
        {ExportFormat::WebM, tr("WebM video (VP9)")},
        {ExportFormat::Apng, tr("Animated PNG (APNG)")},
        {ExportFormat::Html, tr("HTML flipbook (one file)")},
        {ExportFormat::Lottie, tr("Lottie animation (JSON), for web pages and apps")},
        {ExportFormat::DotLottie, tr("dotLottie animation (compressed Lottie)")},
        {ExportFormat::PngSequence, tr("PNG images (a folder)")},
        {ExportFormat::SvgSequence, tr("SVG vector images (a folder)")},
        {ExportFormat::Obj, tr("3D model (OBJ), the current frame")},
        {ExportFormat::Glb, tr("3D model (glTF binary), the current frame")}};
    for (const auto &[format, label] : formats)
        m_format->addItem(label, int(format));
    m_target = new QLineEdit(this);
    m_browse = new QPushButton(tr("&Browse..."), this);
    m_range = new QComboBox(this);
    m_range->addItem(tr("Play range"), int(Range::PlayRange));
    m_range->addItem(tr("All frames"), int(Range::AllFrames));
    m_range->addItem(tr("Frames"), int(Range::Custom));
    m_first = new QSpinBox(this);
    m_last = new QSpinBox(this);
    for (QSpinBox *box : {m_first, m_last})
        box->setRange(1, std::max(1, shotFrameCount()));
    m_first->setValue(m_doc.playFirst() + 1);
    m_last->setValue(m_doc.playLast() + 1);
    m_scale = new QDoubleSpinBox(this);
    m_scale->setRange(0.05, 8.0);
    m_scale->setDecimals(2);
    m_scale->setSingleStep(0.25);
    m_scale->setValue(1.0);
    m_scale->setSuffix(QStringLiteral(" \u00d7"));
    m_pixels = new QLabel(this);
    m_background = new QComboBox(this);
    m_background->addItem(tr("Document background"), int(Background::Document));
    m_background->addItem(tr("Transparent"), int(Background::Transparent));
    m_background->addItem(tr("Colour"), int(Background::Colour));
    m_colour = new ColorButton(Qt::white, this);
    m_fps = new QSpinBox(this);
    m_fps->setRange(model::kMinFps, model::kMaxFps);
    m_fps->setSuffix(tr(" fps"));
    m_loop = new QCheckBox(tr("Start again after the last frame"), this);
    m_perDrawing = new QCheckBox(tr("One file per drawing, with an exposure sheet"), this);
    m_includeReference = new QCheckBox(tr("Include refere&nce"), this);
    m_includeReference->setToolTip(
        tr("Paint the reference picture or video under the drawing (not in SVG or 3D)"));
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("export.status"));
    m_status->setWordWrap(true);

    layOut();
    connectFields();
}

void ExportDialog::layOut()
{
    auto *target = new QHBoxLayout;
    target->addWidget(m_target, 1);
    target->addWidget(m_browse);
    auto *range = new QHBoxLayout;
    range->addWidget(m_range);
    range->addWidget(m_first);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_last);
    auto *scale = new QHBoxLayout;
    scale->addWidget(m_scale);
    scale->addWidget(m_pixels, 1);
    auto *background = new QHBoxLayout;
    background->addWidget(m_background, 1);
    background->addWidget(m_colour);
    // Rows holding a layout need their label's buddy set by hand for the mnemonic to work.
    const auto label = [this](const QString &text, QWidget *buddy) {
        auto *l = new QLabel(text, this);
        l->setBuddy(buddy);
        return l;
    };
    auto *form = new QFormLayout;
    form->addRow(label(tr("&Format:"), m_format), m_format);
    form->addRow(label(tr("&Save to:"), m_target), target);
    form->addRow(label(tr("F&rames:"), m_range), range);
    form->addRow(label(tr("Sc&ale:"), m_scale), scale);
    form->addRow(label(tr("&Background:"), m_background), background);
    form->addRow(label(tr("Frame ra&te:"), m_fps), m_fps);
    form->addRow(tr("Loop:"), m_loop);
    form->addRow(QString(), m_perDrawing);
    form->addRow(QString(), m_includeReference);

    m_buttons = new QDialogButtonBox(this);
    m_exportButton = m_buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole);
    m_cancelButton = m_buttons->addButton(tr("Cancel Export"), QDialogButtonBox::ActionRole);
    m_closeButton = m_buttons->addButton(QDialogButtonBox::Close);
    m_cancelButton->setVisible(false);
    m_exportButton->setDefault(true);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);
}

void ExportDialog::connectFields()
{
    connect(m_exportButton, &QPushButton::clicked, this, &ExportDialog::startExport);
    connect(m_cancelButton, &QPushButton::clicked, this, &ExportDialog::cancelExport);
    connect(m_closeButton, &QPushButton::clicked, this, &ExportDialog::reject);
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString path = askTargetPath();
        if (!path.isEmpty())
            setTarget(path);
    });
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
    for (QComboBox *box : {m_range, m_background})
        connect(box, &QComboBox::currentIndexChanged, this, &ExportDialog::updateFields);
    connect(m_scale, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateFields);
}

void ExportDialog::setFormat(ExportFormat format)
{
    m_format->setCurrentIndex(m_format->findData(int(format)));
}

void ExportDialog::setTarget(const QString &path)
{
    m_target->setText(QDir::toNativeSeparators(path));
}

int ExportDialog::shotFrameCount() const
{
    return m_doc.layerCount() == 1 ? m_doc.frameCount()
                                   : int(model::shotFrames(m_doc.layers()).size());
}

void ExportDialog::setCurrentFrame(int index)
{
    index = std::clamp(index, 0, std::max(0, m_doc.frameCount() - 1));
    if (m_doc.layerCount() > 1) {
        // The export's pictures are the composed shot's: the one showing the frame's first tick.
        const qint64 tick = model::celStart(m_doc.frames(), index);
        const std::vector<model::Frame> shot = model::shotFrames(m_doc.layers());
        qint64 start = 0;
        int at = 0;
        for (; at + 1 < int(shot.size()); ++at) {
            start += shot[std::size_t(at)].hold;
            if (tick < start)
                break;
        }
        index = at;
    }
    m_currentFrame = index;
    updateFields();
}

void ExportDialog::formatChanged()
{
    const auto format = ExportFormat(m_format->currentData().toInt());
    if (!m_target->text().isEmpty())
        setTarget(withFormat(stem(QDir::fromNativeSeparators(m_target->text())), format));
    updateFields();
}

void ExportDialog::updateFields()
{
    const auto format = ExportFormat(m_format->currentData().toInt());
    // MP4 has no alpha: its "Transparent" entry is greyed out.
    auto *items = qobject_cast<QStandardItemModel *>(m_background->model());
    if (QStandardItem *item = items ? items->item(int(Background::Transparent)) : nullptr)
        item->setEnabled(model::exportSupportsTransparency(format));
    if (!model::exportSupportsTransparency(format) &&
        m_background->currentData().toInt() == int(Background::Transparent))
        m_background->setCurrentIndex(int(Background::Document));
    // A 3D model is the current frame, in canvas units, without background or rate.
    const bool flat = !model::exportsModel(format);
    const bool custom = m_range->currentData().toInt() == int(Range::Custom);
    for (QWidget *field : std::initializer_list<QWidget *>{m_range, m_scale, m_background, m_fps})
        field->setEnabled(flat);
    m_first->setEnabled(flat && custom);
    m_last->setEnabled(flat && custom);
    m_colour->setEnabled(flat && m_background->currentData().toInt() == int(Background::Colour));
    m_loop->setEnabled(model::exportSupportsLoop(format));
    m_perDrawing->setEnabled(model::exportsSequence(format));
    m_includeReference->setEnabled(!m_doc.referenceLayer().isEmpty() &&
                                   format != ExportFormat::SvgSequence &&
                                   format != ExportFormat::Obj);
    // The size only depends on the canvas, scale and format: plan it for one blank frame.
    model::ExportSource probe{{}, m_doc.settings(), {}};
    probe.frames.resize(1);
    model::ExportOptions sizing = options();
    sizing.firstFrame = sizing.lastFrame = -1;
    const auto plan = model::planExport(probe, sizing);
    m_pixels->setText(plan && flat
                          ? tr("%1 x %2 pixels").arg(plan->size.width()).arg(plan->size.height())
                          : QString());
    if (format == ExportFormat::Obj && !isExporting())
        m_status->setText(tr("A 3D model holds the current frame (%1) only: its objects inflated, "
                             "in their fill colours, with a .mtl file beside it. The frames, "
                             "scale, background and frame rate do not apply.")
                              .arg(m_currentFrame + 1));
    else if (!flat && !isExporting())
        m_status->setText(tr("A 3D model holds the current frame (%1) only: its objects inflated, "
                             "in their fill colours, all in one file. The frames, scale, "
                             "background and frame rate do not apply.")
                              .arg(m_currentFrame + 1));
    else if (model::exportNeedsFfmpeg(format) && model::ffmpegProgram().isEmpty())
        m_status->setText(tr("This format needs the ffmpeg program, which was not found; "
                             "install it (on Debian: apt install ffmpeg) first."));
    else if (!m_doc.soundtrack().isEmpty() && !isExporting())
        m_status->setText(
            format == ExportFormat::Mp4 || format == ExportFormat::WebM
                ? tr("The video carries the soundtrack, trimmed to the frames exported.")
            : format == ExportFormat::Html
                ? tr("The page carries the soundtrack; it plays with the frames once the viewer "
                     "presses Play.")
                : tr("This format has no sound: the soundtrack is left out (MP4, WebM and HTML "
                     "carry it)."));
    else if (!isExporting())
        m_status->clear();
}

model::ExportOptions ExportDialog::options() const
{
    model::ExportOptions o;
    o.format = ExportFormat(m_format->currentData().toInt());
    o.target = QDir::fromNativeSeparators(m_target->text().trimmed());
    switch (Range(m_range->currentData().toInt())) {
    case Range::AllFrames:
        o.firstFrame = 0;
        o.lastFrame = std::max(0, shotFrameCount() - 1);
        break;
    case Range::Custom:
        o.firstFrame = m_first->value() - 1;
        o.lastFrame = m_last->value() - 1;
        break;
    default:
        break;
    }
    if (model::exportsModel(o.format)) // whatever the (disabled) range says
        o.firstFrame = o.lastFrame = m_currentFrame;
    o.scale = m_scale->value();
    const auto background = Background(m_background->currentData().toInt());
    o.transparent = background == Background::Transparent;
    if (background == Background::Colour)
        o.background = m_colour->color().rgb();
    o.fps = m_fps->value();
    o.loop = m_loop->isChecked();
    o.onePerDrawing = m_perDrawing->isChecked() && model::exportsSequence(o.format);
    o.includeReference = m_includeReference->isEnabled() && m_includeReference->isChecked();
    o.title =
        m_documentPath.isEmpty() ? tr("untitled") : QFileInfo(m_documentPath).completeBaseName();
    return o;
}

QString ExportDialog::askTargetPath()
{
    const auto format = ExportFormat(m_format->currentData().toInt());
    const QString current = QDir::fromNativeSeparators(m_target->text());
    if (model::exportsSequence(format))
        return QFileDialog::getExistingDirectory(this, tr("Export to Folder"),
                                                 QFileInfo(current).path());
    const QString suffix = model::exportFormatSuffix(format);
    return QFileDialog::getSaveFileName(this, tr("Export Animation"), current,
                                        tr("%1 files (*.%2)").arg(suffix.toUpper(), suffix),
                                        nullptr, QFileDialog::DontConfirmOverwrite);
}

} // namespace finbook::ui
