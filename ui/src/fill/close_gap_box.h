// The Fill toolbar's "Close gaps" box: the document's close-gap distance (px, or automatic).
#pragma once

#include <QSpinBox>

#include <functional>

namespace finbook::ui {

class CloseGapBox : public QSpinBox {
public:
    // `automaticGap` answers the gap "automatic" closes on the current object (px; < 0 when
    // there is no object).
    CloseGapBox(std::function<double()> automaticGap, QWidget *parent = nullptr);

    // The arrows step by what the eye tells apart: 1 px up to 10, then 5 px up to 50, then 10 px
    // up to 200, then 50 px. Stepping up from automatic starts at the automatic gap, so raising
    // it never first closes less than before.
    void stepBy(int steps) override;
    // Shows the automatic gap of the current object in the "automatic" text.
    void refreshAutomatic();

protected:
    void showEvent(QShowEvent *event) override;

private:
    std::function<double()> m_automaticGap;
};

// The step at `value` going up (`up`) or down.
int closeGapStep(int value, bool up);

} // namespace finbook::ui
