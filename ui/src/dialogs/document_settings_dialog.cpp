#include <finbook/model/commands.h>
#include <finbook/ui/dialogs/document_settings_dialog.h>

#include <QCheckBox>
#include <QColorDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace finbook::ui {

DocumentSettingsDialog::DocumentSettingsDialog(model::Document *document, QWidget *parent)
    : QDialog(parent)
    , m_doc(document)
    , m_fps(new QSpinBox(this))
    , m_width(new QSpinBox(this))
    , m_height(new QSpinBox(this))
    , m_backgroundButton(new QPushButton(this))
    , m_loop(new QCheckBox(tr("Start again after the last frame"), this))
    , m_start(new QSpinBox(this))
    , m_end(new QSpinBox(this))
{
    setWindowTitle(tr("Document Settings"));
    m_fps->setRange(model::kMinFps, model::kMaxFps);
    m_fps->setSuffix(tr(" fps"));
    for (QSpinBox *side : {m_width, m_height}) {
        side->setRange(1, model::kMaxCanvasSide);
        side->setSuffix(tr(" px"));
    }
    const int frames = std::max(1, m_doc->frameCount());
    m_start->setRange(1, frames);
    m_end->setRange(0, frames);
    m_end->setSpecialValueText(tr("Last"));
    connect(m_backgroundButton, &QPushButton::clicked, this,
            &DocumentSettingsDialog::chooseBackground);

    auto *size = new QHBoxLayout;
    size->addWidget(m_width);
    size->addWidget(new QLabel(QStringLiteral("\u00d7"), this));
    size->addWidget(m_height);
    auto *range = new QHBoxLayout;
    range->addWidget(m_start);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_end);

    auto *form = new QFormLayout;
    form->addRow(tr("&Frame rate:"), m_fps);
    form->addRow(tr("Canvas size:"), size);
    form->addRow(tr("&Background:"), m_backgroundButton);
    form->addRow(tr("Loop:"), m_loop);
    form->addRow(tr("Play frames:"), range);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &DocumentSettingsDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &DocumentSettingsDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    setSettings(m_doc->settings());
}

bool DocumentSettingsDialog::edit(model::Document *document, QWidget *parent)
{
    DocumentSettingsDialog dialog(document, parent);
    const model::DocumentSettings before = document->settings();
    return dialog.exec() == QDialog::Accepted && document->settings() != before;
}

void DocumentSettingsDialog::setSettings(const model::DocumentSettings &s)
{
    m_fps->setValue(s.fps);
    m_width->setValue(s.canvasSize.width());
    m_height->setValue(s.canvasSize.height());
    setBackground(QColor::fromRgba(s.background));
    m_loop->setChecked(s.loop);
    m_start->setValue(s.playStart + 1);
    m_end->setValue(s.playEnd < 0 ? 0 : s.playEnd + 1);
}

model::DocumentSettings DocumentSettingsDialog::settings() const
{
    model::DocumentSettings s = m_doc->settings();
    s.fps = m_fps->value();
    s.canvasSize = QSize(m_width->value(), m_height->value());
    s.background = m_background.rgba();
    s.loop = m_loop->isChecked();
    s.playStart = m_start->value() - 1;
    s.playEnd = m_end->value() == 0 ? -1 : m_end->value() - 1;
    return model::sanitizedSettings(s);
}

bool DocumentSettingsDialog::apply()
{
    const model::DocumentSettings s = settings();
    if (s == m_doc->settings())
        return false;
    m_doc->undoStack()->push(new model::ChangeSettingsCommand(m_doc, s));
    return true;
}

void DocumentSettingsDialog::accept()
{
    apply();
    QDialog::accept();
}

void DocumentSettingsDialog::setBackground(QColor color)
{
    m_background = color;
    QPixmap swatch(32, 16);
    swatch.fill(color);
    QPainter(&swatch).drawRect(swatch.rect().adjusted(0, 0, -1, -1));
    m_backgroundButton->setIcon(QIcon(swatch));
    m_backgroundButton->setText(color.name(QColor::HexRgb).toUpper());
}

void DocumentSettingsDialog::chooseBackground()
{
    const QColor chosen = QColorDialog::getColor(m_background, this, tr("Background Colour"));
    if (chosen.isValid())
        setBackground(chosen);
}

} // namespace finbook::ui
