// The pen's toolbar: colour swatches (two rows, named "swatch#rrggbb"), a colour picker,
// width and smoothing.
#pragma once

#include <QToolBar>

class QDoubleSpinBox;
class QSpinBox;

namespace finbook::ui {

class ColorButton;
class PenTool;

class BrushToolBar : public QToolBar {
    Q_OBJECT
public:
    explicit BrushToolBar(PenTool *pen, QWidget *parent = nullptr);

private:
    QWidget *createSwatches(const QList<QColor> &colors);
    void showSettings();

    PenTool *m_pen;
    ColorButton *m_color;
    QDoubleSpinBox *m_width;
    QSpinBox *m_smoothing;
    QSpinBox *m_stabiliser;
};

} // namespace finbook::ui
