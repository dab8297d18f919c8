#include <finbook/ui/tools/brush_tool_bar.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/widgets/color_button.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QSpinBox>
#include <QToolButton>

namespace finbook::ui {

BrushToolBar::BrushToolBar(PenTool *pen, QWidget *parent)
    : QToolBar(tr("Brush"), parent)
    , m_pen(pen)
    , m_swatches(new QWidget(this))
    , m_color(new ColorButton(Qt::black, this))
    , m_width(new QDoubleSpinBox(this))
    , m_smoothing(new QSpinBox(this))
    , m_stabiliser(new QSpinBox(this))
    , m_pressure(new QCheckBox(tr("Pressure"), this))
{
    setObjectName(QStringLiteral("brushToolBar"));
    // Two rows of small swatches: a one-row strip took a fifth of a 1280 px window, and the
    // top row must leave room for the deformation tools.
    m_swatches->setObjectName(QStringLiteral("penSwatches"));
    auto *grid = new QGridLayout(m_swatches);
    grid->setContentsMargins(2, 0, 2, 0);
    grid->setSpacing(1);
    setPalette(model::defaultPalette());
    addWidget(m_swatches);
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
    addWidget(new QLabel(tr("Stabiliser:"), this));
    m_stabiliser->setObjectName(QStringLiteral("penStabiliser"));
    m_stabiliser->setRange(0, PenTool::kMaxStabiliser);
    m_stabiliser->setSpecialValueText(tr("Off"));
    m_stabiliser->setToolTip(tr("Steadies the line while you draw: the ink follows the pen on a "
                                "string this long (4 screen pixels a step), so a shaky hand "
                                "draws a smooth line. Off: the ink is under the pen."));
    addWidget(m_stabiliser);
    m_pressure->setObjectName(QStringLiteral("penPressure"));
    m_pressure->setToolTip(tr("A tablet's pressure sets the line's width; off, every line has "
                              "the full width"));
    m_pressure->setFocusPolicy(Qt::NoFocus);
    addWidget(m_pressure);
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
    connect(m_stabiliser, &QSpinBox::valueChanged, this, [this](int v) {
        PenSettings s = m_pen->settings();
        s.stabiliser = v;
        m_pen->setSettings(s);
    });
    connect(m_pressure, &QCheckBox::toggled, this, [this](bool on) {
        PenSettings s = m_pen->settings();
        s.pressure = on;
        m_pen->setSettings(s);
    });
    connect(m_pen, &PenTool::settingsChanged, this, &BrushToolBar::showSettings);
}

void BrushToolBar::setPalette(const model::Palette &palette)
{
    constexpr int kColumns = 5;
    constexpr int kShown = 10;
    constexpr int kCell = 14;
    auto *grid = static_cast<QGridLayout *>(m_swatches->layout());
    while (QLayoutItem *item = grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    const int n = std::min(kShown, int(palette.swatches.size()));
    for (int i = 0; i < n; ++i) {
        const model::Swatch &s = palette.swatches[std::size_t(i)];
        const QColor color = QColor::fromRgb(s.color);
        QPixmap pixmap(kCell - 2, kCell - 2);
        pixmap.fill(color);
        QPainter(&pixmap).drawRect(pixmap.rect().adjusted(0, 0, -1, -1));
        auto *swatch = new QToolButton(m_swatches);
        swatch->setObjectName(QStringLiteral("swatch") + color.name());
        swatch->setAutoRaise(true);
        swatch->setFocusPolicy(Qt::NoFocus);
        swatch->setIcon(QIcon(pixmap));
        swatch->setIconSize(pixmap.size());
        swatch->setFixedSize(kCell, kCell);
        swatch->setToolTip(s.name.isEmpty() ? tr("Pen colour %1").arg(color.name())
                                            : tr("Pen colour %1 (%2)").arg(s.name, color.name()));
        connect(swatch, &QToolButton::clicked, m_color,
                [this, color] { m_color->setColor(color); });
        grid->addWidget(swatch, i / kColumns, i % kColumns);
    }
}

void BrushToolBar::showSettings()
{
    const PenSettings &s = m_pen->settings();
    const QSignalBlocker b1(m_color), b2(m_width), b3(m_smoothing), b4(m_stabiliser),
        b5(m_pressure);
    m_pressure->setChecked(s.pressure);
    m_color->setColor(s.color);
    // Only when different: setValue() rewrites the text, and while the user types "2.5" the
    // pen already follows "2" (keyboard tracking), so "2" would become "2.0 px" mid-typing.
    if (m_width->value() != s.width)
        m_width->setValue(s.width);
    if (m_smoothing->value() != s.smoothing)
        m_smoothing->setValue(s.smoothing);
    if (m_stabiliser->value() != s.stabiliser)
        m_stabiliser->setValue(s.stabiliser);
}

} // namespace finbook::ui
