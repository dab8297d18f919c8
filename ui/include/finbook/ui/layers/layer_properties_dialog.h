// Layer → Layer Properties: name, opacity, multiplane depth and onion skin of one layer, applied
// as one undo step by whoever opened it (LayerActions).
#pragma once

#include <finbook/model/types.h>

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace finbook::ui {

class LayerPropertiesDialog : public QDialog {
    Q_OBJECT
public:
    LayerPropertiesDialog(const model::LayerProperties &properties, QWidget *parent = nullptr);
    // What the dialog shows now (visibility and lock as they came in).
    model::LayerProperties properties() const;

private:
    model::LayerProperties m_properties;
    QLineEdit *m_name;
    QSpinBox *m_opacity;
    QDoubleSpinBox *m_depth;
    QCheckBox *m_onion;
};

} // namespace finbook::ui
