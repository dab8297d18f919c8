#include <finbook/ui/brush_tool_bar.h>
#include <finbook/ui/color_button.h>
#include <finbook/ui/tool_pen.h>

#include <QDoubleSpinBox>
#include <QLabel>
#include <QPainter>
#include <QSpinBox>

namespace finbook::ui {

BrushToolBar::BrushToolBar(PenTool *pen, QWidget *parent)
    : QToolBar(tr("Brush"), parent)
    , m_pen(pen)
    , m_color(new ColorButton(Qt::black, this))
    , m_width(new QDoubleSpinBox(this))
    , m_smoothing(new QSpinBox(this))
{
    setObjectName(QStringLiteral("brushToolBar"));
    for (const QColor &c :
         {QColor(Qt::black), QColor(0x80, 0x80, 0x80), QColor(0xd0, 0x30, 0x30),
          QColor(0xf0, 0x90, 0x20), QColor(0xe8, 0xd0, 0x20), QColor(0x30, 0xa0, 0x40),
          QColor(0x30, 0x60, 0xd0), QColor(0x90, 0x40, 0xb0), QColor(Qt::white)})
        addSwatch(c);
    m_color->setObjectName(QStringLiteral("penColor"));
    addWidget(m_color);
    addSeparator();
    addWidget(new QLabel(tr("Width:"), this));
    m_width->setObjectName(QStringLiteral("penWidth"));
    m_width->setRange(PenTool::kMinWidth, PenTool::kMaxWidth);
    m_width->setDecimals(1);
    m_width->setSingleStep(0.5);
    m_width->setSuffix(tr(" px"));
    addWidget(m_width);
    addWidget(new QLabel(tr("Smoothing:"), this));
    m_smoothing->setObjectName(QStringLiteral("penSmoothing"));
    m_smoothing->setRange(0, PenTool::kMaxSmoothing);
    m_smoothing->setToolTip(tr("How much a stroke is smoothed when the pen lifts"));
    addWidget(m_smoothing);
    showSettings();

    connect(m_color, &ColorButton::colorChanged, this, [this](const QColor &c) {
        PenSettings s = m_pen->settings();
        s.color = c;
        m_pen->setSettings(s);
    });
    connect(m_width, &QDoubleSpinBox::valueChanged, this, [this](double w) {
        PenSettings s = m_pen->settings();
        s.width = w;
        m_pen->setSettings(s);
    });
    connect(m_smoothing, &QSpinBox::valueChanged, this, [this](int v) {
        PenSettings s = m_pen->settings();
        s.smoothing = v;
        m_pen->setSettings(s);
    });
    connect(m_pen, &PenTool::settingsChanged, this, &BrushToolBar::showSettings);
}

void BrushToolBar::addSwatch(const QColor &color)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(color);
    QPainter(&pixmap).drawRect(0, 0, 15, 15);
    QAction *swatch = addAction(QIcon(pixmap), color.name());
    swatch->setToolTip(tr("Pen colour %1").arg(color.name()));
    connect(swatch, &QAction::triggered, m_color, [this, color] { m_color->setColor(color); });
}

void BrushToolBar::showSettings()
{
    const PenSettings &s = m_pen->settings();
    const QSignalBlocker b1(m_color), b2(m_width), b3(m_smoothing);
    m_color->setColor(s.color);
    m_width->setValue(s.width);
    m_smoothing->setValue(s.smoothing);
}

} // namespace finbook::ui
