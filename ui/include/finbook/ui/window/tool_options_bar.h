// ToolOptionsBar: one bar whose content follows the tool in hand, as in Krita and Pencil2D:
// the pen's colour, width, smoothing and stabiliser; the eraser's size and mode; the pins' mesh
// density; the cage's corners and Fit Cage; the bones' skinning and refinement sliders; the
// fill's gap size. Nothing of another tool shows, and the bar keeps its height whatever is in
// hand (it is as tall as its tallest page). A tool without options shows what it does.
#pragma once

#include <QHash>
#include <QToolBar>

class QLabel;
class QStackedWidget;

namespace finbook::ui {

class CanvasTool;
class CanvasWidget;

class ToolOptionsBar : public QToolBar {
    Q_OBJECT
public:
    explicit ToolOptionsBar(CanvasWidget *canvas, QWidget *parent = nullptr);

    // `page` (its own small toolbar, or any widget) shows while one of `toolIds` is in hand.
    void addPage(QWidget *page, const QStringList &toolIds);
    // A new empty page for `toolIds`: a toolbar to add the tool's controls and actions to.
    QToolBar *newPage(const QString &objectName, const QStringList &toolIds);
    QWidget *pageFor(const QString &toolId) const; // null: the tool shows its description

private:
    void follow(CanvasTool *tool);

    CanvasWidget *m_canvas;
    QStackedWidget *m_stack;
    QLabel *m_about; // the page of a tool without options
    QHash<QString, QWidget *> m_pages;
};

} // namespace finbook::ui
