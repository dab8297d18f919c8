#include <finbook/ui/tools/eraser_tool_bar.h>
#include <finbook/ui/tools/tool_eraser.h>

#include <QActionGroup>
#include <QDoubleSpinBox>
#include <QLabel>

namespace finbook::ui {

EraserToolBar::EraserToolBar(EraserTool *eraser, QWidget *parent)
    : QToolBar(tr("Eraser"), parent)
    , m_eraser(eraser)
    , m_cut(new QAction(tr("Cut Lines"), this))
    , m_whole(new QAction(tr("Whole Strokes"), this))
    , m_size(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("eraserToolBar"));
    auto *modes = new QActionGroup(this);
    for (QAction *a : {m_cut, m_whole}) {
        a->setCheckable(true);
        modes->addAction(a);
        addAction(a);
    }
    m_cut->setObjectName(QStringLiteral("eraser.cut"));
    m_cut->setToolTip(tr("Erase the part of a line under the eraser (the rest is split into "
                         "pieces)"));
    m_whole->setObjectName(QStringLiteral("eraser.wholeStrokes"));
    m_whole->setToolTip(tr("Erase every stroke the eraser touches (or hold Shift when you "
                           "start rubbing)"));
    addSeparator();
    addWidget(new QLabel(tr("Size:"), this));
    m_size->setObjectName(QStringLiteral("eraserSize"));
    m_size->setRange(EraserTool::kMinSize, EraserTool::kMaxSize);
    m_size->setDecimals(0);
    m_size->setSuffix(tr(" px"));
    m_size->setToolTip(tr("The eraser's diameter on the canvas"));
    addWidget(m_size);
    showSettings();

    connect(m_cut, &QAction::triggered, this, [this] { m_eraser->setMode(EraserMode::Cut); });
    connect(m_whole, &QAction::triggered, this,
            [this] { m_eraser->setMode(EraserMode::WholeStrokes); });
    connect(m_size, &QDoubleSpinBox::valueChanged, m_eraser, &EraserTool::setSize);
    connect(m_eraser, &EraserTool::modeChanged, this, &EraserToolBar::showSettings);
    connect(m_eraser, &EraserTool::sizeChanged, this, &EraserToolBar::showSettings);
}

void EraserToolBar::showSettings()
{
    const QSignalBlocker block(m_size);
    (m_eraser->mode() == EraserMode::Cut ? m_cut : m_whole)->setChecked(true);
    if (m_size->value() != m_eraser->size())
        m_size->setValue(m_eraser->size());
}

} // namespace finbook::ui
