// The eraser's toolbar, shown while the eraser is the current tool: its mode (cut lines or
// whole strokes) and its size.
#pragma once

#include <QToolBar>

class QActionGroup;
class QDoubleSpinBox;

namespace finbook::ui {

class EraserTool;

class EraserToolBar : public QToolBar {
    Q_OBJECT
public:
    explicit EraserToolBar(EraserTool *eraser, QWidget *parent = nullptr);

private:
    void showSettings();

    EraserTool *m_eraser;
    QAction *m_cut;
    QAction *m_whole;
    QDoubleSpinBox *m_size;
};

} // namespace finbook::ui
