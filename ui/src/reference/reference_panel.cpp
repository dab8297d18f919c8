// ReferencePanel: one row per property, each pushing a merging reference command.
#include <finbook/model/document.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/ui/reference/reference_panel.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>

#include <cmath>

namespace finbook::ui {

namespace {
QDoubleSpinBox *spinBox(double min, double max, int decimals, const QString &suffix,
                        QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    return box;
}
} // namespace

ReferencePanel::ReferencePanel(model::Document *document, QWidget *parent)
    : QWidget(parent)
    , m_doc(document)
{
    m_name = new QLabel(this);
    m_name->setWordWrap(true);
    m_visible = new QCheckBox(tr("&Visible"), this);
    m_locked = new QCheckBox(tr("Loc&ked"), this);
    m_opacity = new QSlider(Qt::Horizontal, this);
    m_opacity->setRange(0, 100);
    m_x = spinBox(-1e6, 1e6, 1, tr(" px"), this);
    m_y = spinBox(-1e6, 1e6, 1, tr(" px"), this);
    m_scale = spinBox(0.1, 100000.0, 1, tr(" %"), this);
    m_rotation = spinBox(-360.0, 360.0, 1, tr(" °"), this);
    m_rate = spinBox(0.0, model::kMaxReferenceRate, 2, tr(" fps"), this);
    m_rate->setSpecialValueText(tr("Document rate"));
    m_rateLabel = new QLabel(this);
    m_rateLabel->setBuddy(m_rate);
    m_remove = new QPushButton(tr("&Remove Reference"), this);

    auto *form = new QFormLayout(this);
    form->addRow(m_name);
    form->addRow(m_visible);
    form->addRow(m_locked);
    form->addRow(tr("Opacity:"), m_opacity);
    form->addRow(tr("Centre X:"), m_x);
    form->addRow(tr("Centre Y:"), m_y);
    form->addRow(tr("Scale:"), m_scale);
    form->addRow(tr("Rotation:"), m_rotation);
    form->addRow(m_rateLabel, m_rate);
    form->addRow(m_remove);

    using model::ReferenceEdit;
    connect(m_visible, &QCheckBox::toggled, this, [this] { edit(ReferenceEdit::Visible); });
    connect(m_locked, &QCheckBox::toggled, this, [this] { edit(ReferenceEdit::Locked); });
    connect(m_opacity, &QSlider::valueChanged, this, [this] { edit(ReferenceEdit::Opacity); });
    for (QDoubleSpinBox *box : {m_x, m_y})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { edit(ReferenceEdit::Place); });
    connect(m_scale, &QDoubleSpinBox::valueChanged, this, [this] { edit(ReferenceEdit::Scale); });
    connect(m_rotation, &QDoubleSpinBox::valueChanged, this,
            [this] { edit(ReferenceEdit::Rotation); });
    connect(m_rate, &QDoubleSpinBox::valueChanged, this, [this] { edit(ReferenceEdit::Rate); });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        if (auto command = model::removeReferenceCommand(m_doc))
            m_doc->undoStack()->push(command.release());
    });
    connect(&m_doc->referenceLayer(), &model::ReferenceLayer::referenceChanged, this,
            &ReferencePanel::refresh);
    refresh();
}

void ReferencePanel::refresh()
{
    const model::Reference &r = m_doc->referenceLayer().reference();
    const bool has = !r.isEmpty();
    m_refreshing = true;
    m_name->setText(has ? r.name
                        : tr("No reference. File → Import Reference… puts a picture or "
                             "a video under the drawing."));
    m_visible->setChecked(r.visible);
    m_locked->setChecked(r.locked);
    m_opacity->setValue(int(std::lround(r.opacity * 100.0)));
    m_x->setValue(r.center.x());
    m_y->setValue(r.center.y());
    m_scale->setValue(r.scale * 100.0);
    m_rotation->setValue(r.rotation);
    m_rate->setValue(r.rate);
    m_refreshing = false;
    for (QWidget *w : std::initializer_list<QWidget *>{m_visible, m_locked, m_opacity, m_remove})
        w->setEnabled(has);
    for (QWidget *w : std::initializer_list<QWidget *>{m_x, m_y, m_scale, m_rotation})
        w->setEnabled(has && !r.locked);
    const bool sequence = r.kind == model::ReferenceKind::Sequence;
    m_rate->setEnabled(has && (r.kind == model::ReferenceKind::Video || sequence));
    // The two kinds count the other way round (reference.h): say which, on the label too.
    m_rateLabel->setText(sequence ? tr("Picture rate:") : tr("Video rate:"));
    m_rate->setToolTip(
        sequence ? tr("Pictures per second of animation. At the document's rate every frame shows "
                      "the next picture; a lower rate holds each picture for several frames.")
                 : tr("Animation frames per second of video. At the document's rate the video "
                      "plays in real time; a higher rate plays it slower, spreading each second "
                      "over more frames."));
    m_rateLabel->setToolTip(m_rate->toolTip());
}

void ReferencePanel::edit(model::ReferenceEdit edit)
{
    if (m_refreshing)
        return;
    // Only the field edited: the others show rounded values that must not leak back.
    model::Reference r = m_doc->referenceLayer().reference();
    switch (edit) {
    case model::ReferenceEdit::Visible:
        r.visible = m_visible->isChecked();
        break;
    case model::ReferenceEdit::Locked:
        r.locked = m_locked->isChecked();
        break;
    case model::ReferenceEdit::Opacity:
        r.opacity = m_opacity->value() / 100.0;
        break;
    case model::ReferenceEdit::Place:
        r.center = QPointF(m_x->value(), m_y->value());
        break;
    case model::ReferenceEdit::Scale:
        r.scale = m_scale->value() / 100.0;
        break;
    case model::ReferenceEdit::Rotation:
        r.rotation = m_rotation->value();
        break;
    case model::ReferenceEdit::Rate:
        r.rate = m_rate->value();
        break;
    case model::ReferenceEdit::Replace:
        return;
    }
    if (auto command = model::editReferenceCommand(m_doc, r, edit))
        m_doc->undoStack()->push(command.release());
    else
        refresh(); // refused (locked, out of range): show what the reference still is
}

std::optional<QString> importReference(model::Document &document, const QString &path)
{
    return importReference(document, QStringList{path});
}

std::optional<QString> importReference(model::Document &document, const QStringList &paths)
{
    auto reference = model::importReferenceSequence(paths, QSizeF(document.settings().canvasSize));
    if (!reference)
        return reference.error();
    auto command = model::importReferenceCommand(&document, std::move(*reference));
    if (!command)
        return ReferencePanel::tr("The reference could not be placed on the canvas.");
    document.undoStack()->push(command.release());
    return std::nullopt;
}

QStringList chooseReferenceFiles(QWidget *parent, const QString &folder)
{
    QStringList paths = QFileDialog::getOpenFileNames(
        parent, ReferencePanel::tr("Import Reference"), folder, referenceFileFilter());
    if (paths.size() != 1)
        return paths;
    const QStringList run = model::numberedSequence(paths.front());
    if (run.size() < 2)
        return paths;
    const auto answer = QMessageBox::question(
        parent, ReferencePanel::tr("Import Reference"),
        ReferencePanel::tr("“%1” is one of %n numbered pictures (%2 … %3). Import them all as "
                           "a sequence, one picture per frame?",
                           nullptr, int(run.size()))
            .arg(QFileInfo(paths.front()).fileName(), QFileInfo(run.front()).fileName(),
                 QFileInfo(run.back()).fileName()),
        QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel, QMessageBox::Yes);
    if (answer == QMessageBox::Cancel)
        return {};
    return answer == QMessageBox::Yes ? run : paths;
}

QString referenceFileFilter()
{
    return ReferencePanel::tr("Pictures and videos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif "
                              "*.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;All files (*)");
}

} // namespace finbook::ui
