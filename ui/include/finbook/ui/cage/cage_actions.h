// The cage's actions: Fit Cage (a coarse cage around the current object in one step, with an
// adjustable corner count) and Edit Cage Shape (the Cage tool's rest-editing mode). Also the
// overlay that draws every cage of the current frame: the rest outline faint, the posed cage
// bold, tinted when it crosses itself.
#pragma once

#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QAction>
#include <QObject>

class QSpinBox;

namespace finbook::ui {

class CageTool;
class EditorState;

class CageActions : public QObject {
    Q_OBJECT
public:
    CageActions(EditorState *state, model::DeformController *controller, CageTool *tool,
                QObject *parent = nullptr);

    QAction *fitAction() const { return m_fit; }
    QAction *editShapeAction() const { return m_editShape; }
    QList<QAction *> actions() const { return {m_fit, m_editShape}; }
    // How many corners Fit Cage aims for (remembered across sessions).
    int fitCorners() const { return m_corners; }
    void setFitCorners(int corners);
    QSpinBox *createCornersSpinBox(QWidget *parent);
    // Fits a cage to the current object; false (with a message) when it cannot.
    bool fitCage();

signals:
    void messagePosted(const QString &message);
    void fitCornersChanged(int corners);

private:
    void updateEnabled();

    EditorState *m_state;
    model::DeformController *m_controller;
    CageTool *m_tool;
    QAction *m_fit;
    QAction *m_editShape;
    int m_corners;
};

class CageOverlay : public CanvasOverlay {
public:
    CageOverlay(EditorState *state, CageTool *tool);
    void paint(QPainter &painter, const QTransform &canvasToWidget) override;

private:
    EditorState *m_state;
    CageTool *m_tool;
};

} // namespace finbook::ui
