#include <finbook/ui/widgets/color_button.h>

#include <QColorDialog>
#include <QPainter>
#include <QPixmap>

namespace finbook::ui {

ColorButton::ColorButton(const QColor &color, QWidget *parent)
    : QToolButton(parent)
    , m_color(color)
{
    setToolTip(tr("Choose a colour"));
    setIconSize(QSize(20, 20));
    updateIcon();
    connect(this, &QToolButton::clicked, this, &ColorButton::chooseColor);
}

void ColorButton::setColor(const QColor &color)
{
    if (!color.isValid() || color == m_color)
        return;
    m_color = color;
    updateIcon();
    emit colorChanged(m_color);
}

void ColorButton::chooseColor()
{
    const QColor chosen =
        QColorDialog::getColor(m_color, this, tr("Choose Colour"), QColorDialog::ShowAlphaChannel);
    if (chosen.isValid())
        setColor(chosen);
}

void ColorButton::updateIcon()
{
    QPixmap pixmap(iconSize());
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setPen(QPen(palette().color(QPalette::WindowText), 1));
    painter.setBrush(m_color);
    painter.drawRect(QRectF(pixmap.rect()).adjusted(0.5, 0.5, -0.5, -0.5));
    painter.end();
    setIcon(QIcon(pixmap));
}

} // namespace finbook::ui
