// The graph of a camera key's Bézier easing: time across, the share of the way up, from (0, 0)
// to (1, 1). Two handles set the inner control points (as CSS's cubic-bezier(): x within
// [0, 1] so time only goes forward, y may overshoot to −0.5 … 1.5); presets put them where the
// usual easings are. BezierEditorDialog wraps it with OK and Cancel.
#pragma once

#include <QDialog>
#include <QPointF>
#include <QWidget>

namespace finbook::ui {

class BezierEditor : public QWidget {
    Q_OBJECT
public:
    explicit BezierEditor(QWidget *parent = nullptr);

    QPointF control1() const { return m_c[0]; }
    QPointF control2() const { return m_c[1]; }
    void setControls(QPointF c1, QPointF c2);
    QSize sizeHint() const override { return {260, 260}; }
    // The widget point of a graph point, and back.
    QPointF toWidget(QPointF graph) const;
    QPointF toGraph(QPointF widget) const;

signals:
    void controlsChanged();

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    QRectF graphRect() const; // the unit square in widget px
    QPointF m_c[2];
    int m_dragging = -1;
};

class BezierEditorDialog : public QDialog {
    Q_OBJECT
public:
    BezierEditorDialog(QPointF c1, QPointF c2, QWidget *parent = nullptr);
    QPointF control1() const { return m_editor->control1(); }
    QPointF control2() const { return m_editor->control2(); }
    BezierEditor *editor() const { return m_editor; }

private:
    BezierEditor *m_editor;
};

} // namespace finbook::ui
