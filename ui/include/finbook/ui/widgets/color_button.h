// A button showing a colour; clicking it opens QColorDialog.
#pragma once

#include <QColor>
#include <QToolButton>

namespace finbook::ui {

class ColorButton : public QToolButton {
    Q_OBJECT
public:
    explicit ColorButton(const QColor &color = Qt::black, QWidget *parent = nullptr);

    QColor color() const { return m_color; }
    void setColor(const QColor &color);

signals:
    void colorChanged(const QColor &color);

private:
    void chooseColor();
    void updateIcon();

    QColor m_color;
};

} // namespace finbook::ui
