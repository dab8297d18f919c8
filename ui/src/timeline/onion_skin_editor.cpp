#include <finbook/ui/timeline/onion_skin_editor.h>
#include <finbook/ui/widgets/color_button.h>

#include <QCheckBox>
#include <QFormLayout>
#include <QSpinBox>

#include <cmath>

namespace finbook::ui {

OnionSkinEditor::OnionSkinEditor(QWidget *parent)
    : QWidget(parent)
    , m_enabled(new QCheckBox(tr("Show onion skin"), this))
    , m_before(new QSpinBox(this))
    , m_after(new QSpinBox(this))
    , m_opacity(new QSpinBox(this))
    , m_beforeTint(new ColorButton(Qt::red, this))
    , m_afterTint(new ColorButton(Qt::blue, this))
{
    for (QSpinBox *box : {m_before, m_after})
        box->setRange(0, 5);
    m_opacity->setRange(0, 100);
    m_opacity->setSuffix(tr(" %"));
    auto *form = new QFormLayout(this);
    form->addRow(m_enabled);
    form->addRow(tr("Frames before:"), m_before);
    form->addRow(tr("Frames after:"), m_after);
    form->addRow(tr("Opacity of the nearest frame:"), m_opacity);
    form->addRow(tr("Tint before:"), m_beforeTint);
    form->addRow(tr("Tint after:"), m_afterTint);
    setOnionSkin(OnionSkin{});

    const auto edited = [this] { emit onionSkinEdited(onionSkin()); };
    connect(m_enabled, &QCheckBox::toggled, this, edited);
    connect(m_before, &QSpinBox::valueChanged, this, edited);
    connect(m_after, &QSpinBox::valueChanged, this, edited);
    connect(m_opacity, &QSpinBox::valueChanged, this, edited);
    connect(m_beforeTint, &ColorButton::colorChanged, this, edited);
    connect(m_afterTint, &ColorButton::colorChanged, this, edited);
}

OnionSkin OnionSkinEditor::onionSkin() const
{
    OnionSkin o;
    o.enabled = m_enabled->isChecked();
    o.before = m_before->value();
    o.after = m_after->value();
    o.opacity = m_opacity->value() / 100.0;
    o.beforeTint = m_beforeTint->color();
    o.afterTint = m_afterTint->color();
    return o;
}

void OnionSkinEditor::setOnionSkin(const OnionSkin &onion)
{
    const QSignalBlocker b1(m_enabled), b2(m_before), b3(m_after), b4(m_opacity), b5(m_beforeTint),
        b6(m_afterTint);
    m_enabled->setChecked(onion.enabled);
    m_before->setValue(onion.before);
    m_after->setValue(onion.after);
    m_opacity->setValue(int(std::lround(onion.opacity * 100)));
    m_beforeTint->setColor(onion.beforeTint);
    m_afterTint->setColor(onion.afterTint);
}

} // namespace finbook::ui
