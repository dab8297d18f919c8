#include <finbook/ui/layers/layer_properties_dialog.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QSpinBox>

#include <cmath>

namespace finbook::ui {

LayerPropertiesDialog::LayerPropertiesDialog(const model::LayerProperties &properties,
                                             QWidget *parent)
    : QDialog(parent)
    , m_properties(properties)
    , m_name(new QLineEdit(properties.name, this))
    , m_opacity(new QSpinBox(this))
    , m_depth(new QDoubleSpinBox(this))
    , m_onion(new QCheckBox(tr("Show its neighbouring drawings in the onion skin"), this))
{
    setWindowTitle(tr("Layer Properties"));
    setObjectName(QStringLiteral("layerPropertiesDialog"));
    m_name->setObjectName(QStringLiteral("layerName"));
    m_opacity->setObjectName(QStringLiteral("layerOpacity"));
    m_opacity->setRange(0, 100);
    m_opacity->setSuffix(QStringLiteral(" %"));
    m_opacity->setValue(int(std::lround(properties.opacity * 100)));
    m_depth->setObjectName(QStringLiteral("layerDepth"));
    m_depth->setRange(model::kMinLayerDepth, model::kMaxLayerDepth);
    m_depth->setDecimals(2);
    m_depth->setSingleStep(0.1);
    m_depth->setValue(properties.depth);
    m_depth->setToolTip(
        tr("How far behind the page the layer lies: at depth 1 the camera's pans and zooms move "
           "it half as much (a distant background), at 0 exactly as much, below 0 more (a "
           "foreground rushing past)."));
    m_onion->setObjectName(QStringLiteral("layerOnion"));
    m_onion->setChecked(properties.onionSkin);
    auto *form = new QFormLayout(this);
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Opacity:"), m_opacity);
    form->addRow(tr("&Depth:"), m_depth);
    form->addRow(QString(), m_onion);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

model::LayerProperties LayerPropertiesDialog::properties() const
{
    model::LayerProperties p = m_properties;
    p.name = m_name->text().trimmed().isEmpty() ? m_properties.name : m_name->text().trimmed();
    // Values the spin boxes show rounded stay exact when left alone.
    if (m_opacity->value() != int(std::lround(m_properties.opacity * 100)))
        p.opacity = m_opacity->value() / 100.0;
    if (std::abs(m_depth->value() - m_properties.depth) >= 0.005)
        p.depth = m_depth->value();
    p.onionSkin = m_onion->isChecked();
    return p;
}

} // namespace finbook::ui
