// The pen's toolbar: colour swatches (two rows, named "swatch#rrggbb": the document palette's
// first ten), a colour picker, width, smoothing and the stabiliser.
#pragma once

#include <finbook/model/palette/palette.h>

#include <QToolBar>

class QCheckBox;
class QDoubleSpinBox;
class QSpinBox;

namespace finbook::ui {

class ColorButton;
class PenTool;

class BrushToolBar : public QToolBar {
    Q_OBJECT
public:
    explicit BrushToolBar(PenTool *pen, QWidget *parent = nullptr);

    // The swatches show the first ten colours of `palette` (the document's: the Palette panel
    // shows them all and edits them).
    void setPalette(const model::Palette &palette);

private:
    void showSettings();

    PenTool *m_pen;
    QWidget *m_swatches;
    ColorButton *m_color;
    QDoubleSpinBox *m_width;
    QSpinBox *m_smoothing;
    QSpinBox *m_stabiliser;
    QCheckBox *m_pressure;
};

} // namespace finbook::ui
