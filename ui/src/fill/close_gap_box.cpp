// CloseGapBox (close_gap_box.h).
#include "close_gap_box.h"

#include <finbook/ui/window/main_window.h>

#include <cmath>

namespace finbook::ui {

int closeGapStep(int value, bool up)
{
    // Where a step lands on a boundary going down, it uses the finer step below it.
    const int at = up ? value : value - 1;
    if (at < 10)
        return 1;
    if (at < 50)
        return 5;
    if (at < 200)
        return 10;
    return 50;
}

CloseGapBox::CloseGapBox(std::function<double()> automaticGap, QWidget *parent)
    : QSpinBox(parent)
    , m_automaticGap(std::move(automaticGap))
{
    setSpecialValueText(MainWindow::tr("Close gaps: automatic"));
}

void CloseGapBox::refreshAutomatic()
{
    const double gap = m_automaticGap ? m_automaticGap() : -1.0;
    const QString text =
        gap >= 0 ? MainWindow::tr("Close gaps: automatic (%1 px)").arg(int(std::lround(gap)))
                 : MainWindow::tr("Close gaps: automatic");
    if (text == specialValueText())
        return;
    setSpecialValueText(text);
    updateGeometry(); // the toolbar makes room for the longer text
}

void CloseGapBox::showEvent(QShowEvent *event)
{
    refreshAutomatic();
    QSpinBox::showEvent(event);
}

void CloseGapBox::stepBy(int steps)
{
    int v = value();
    if (v < 0 && steps > 0) {
        const double automatic = m_automaticGap ? m_automaticGap() : -1.0;
        v = automatic > 0 ? std::min(int(std::ceil(automatic)), maximum()) : 0;
        --steps;
    }
    for (; steps > 0 && v < maximum(); --steps) {
        const int step = closeGapStep(v, true);
        v = std::min((v / step + 1) * step, maximum()); // onto the coarser grid
    }
    for (; steps < 0 && v >= 0; ++steps) {
        if (v == 0) {
            v = minimum(); // below 0: automatic
            break;
        }
        const int step = closeGapStep(v, false);
        v = (v - 1) / step * step;
    }
    setValue(v);
}

} // namespace finbook::ui
