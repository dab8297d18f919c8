#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/tool_options_bar.h>

#include <QLabel>
#include <QStackedWidget>

namespace finbook::ui {

ToolOptionsBar::ToolOptionsBar(CanvasWidget *canvas, QWidget *parent)
    : QToolBar(tr("Tool Options"), parent)
    , m_canvas(canvas)
    , m_stack(new QStackedWidget(this))
    , m_about(new QLabel(this))
{
    setObjectName(QStringLiteral("toolOptionsBar"));
    m_about->setObjectName(QStringLiteral("toolOptionsAbout"));
    m_about->setContentsMargins(8, 0, 8, 0);
    m_stack->addWidget(m_about);
    addWidget(m_stack);
    connect(canvas, &CanvasWidget::currentToolChanged, this, &ToolOptionsBar::follow);
    follow(canvas->currentTool());
}

void ToolOptionsBar::addPage(QWidget *page, const QStringList &toolIds)
{
    if (m_stack->indexOf(page) < 0)
        m_stack->addWidget(page);
    for (const QString &id : toolIds)
        m_pages.insert(id, page);
    follow(m_canvas->currentTool());
}

QToolBar *ToolOptionsBar::newPage(const QString &objectName, const QStringList &toolIds)
{
    auto *page = new QToolBar(this);
    page->setObjectName(objectName);
    page->setMovable(false);
    page->setFloatable(false);
    page->setIconSize(iconSize());
    page->setToolButtonStyle(toolButtonStyle());
    page->setStyleSheet(QStringLiteral("QToolBar { border: 0px; }"));
    addPage(page, toolIds);
    return page;
}

QWidget *ToolOptionsBar::pageFor(const QString &toolId) const
{
    return m_pages.value(toolId, nullptr);
}

void ToolOptionsBar::follow(CanvasTool *tool)
{
    QWidget *page = tool ? pageFor(tool->id()) : nullptr;
    if (!page) {
        m_about->setText(tool ? tr("%1: %2").arg(tool->name(), tool->description()) : QString());
        page = m_about;
    }
    m_stack->setCurrentWidget(page);
}

} // namespace finbook::ui
