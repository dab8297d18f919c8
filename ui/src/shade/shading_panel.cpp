// The Shading panel (shading_panel.h).
#include "shading_panel.h"

#include <finbook/model/shade/shade_commands.h>
#include <finbook/ui/window/editor_state.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace finbook::ui {

ShadingPanel::ShadingPanel(EditorState *state, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
{
    auto *form = new QFormLayout;
    m_ramp = new QComboBox(this);
    m_ramp->setObjectName(QStringLiteral("shade.ramp"));
    m_ramp->addItem(tr("Flat"), int(model::ShadeRamp::Off));
    m_ramp->addItem(tr("Cel, two tones"), int(model::ShadeRamp::TwoTones));
    m_ramp->addItem(tr("Cel, three tones"), int(model::ShadeRamp::ThreeTones));
    m_ramp->addItem(tr("Smooth"), int(model::ShadeRamp::Smooth));
    m_ramp->setToolTip(tr("Shade the current object's fills from its rounded shape, in every "
                          "frame where the object appears (objects of the same name)"));
    form->addRow(tr("Fills:"), m_ramp);
    m_rim = new QCheckBox(tr("Rim light"), this);
    m_rim->setObjectName(QStringLiteral("shade.rim"));
    m_rim->setToolTip(tr("A light edge on the side away from the light"));
    form->addRow(QString(), m_rim);
    m_azimuth = new QSpinBox(this);
    m_azimuth->setObjectName(QStringLiteral("shade.azimuth"));
    m_azimuth->setRange(0, 359);
    m_azimuth->setWrapping(true);
    m_azimuth->setSuffix(QStringLiteral("°"));
    m_azimuth->setKeyboardTracking(false);
    m_azimuth->setToolTip(tr("Where the light comes from on screen: 0° from the right, 90° from "
                             "above, 180° from the left"));
    form->addRow(tr("Light direction:"), m_azimuth);
    m_elevation = new QSpinBox(this);
    m_elevation->setObjectName(QStringLiteral("shade.elevation"));
    m_elevation->setRange(0, 90);
    m_elevation->setSuffix(QStringLiteral("°"));
    m_elevation->setKeyboardTracking(false);
    m_elevation->setToolTip(tr("How high the light stands above the drawing: 0° grazes it, 90° "
                               "shines from the viewer"));
    form->addRow(tr("Light height:"), m_elevation);
    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_hint);
    layout->addStretch(1);

    connect(m_ramp, &QComboBox::activated, this, &ShadingPanel::shadingEdited);
    connect(m_rim, &QCheckBox::clicked, this, &ShadingPanel::shadingEdited);
    connect(m_azimuth, &QSpinBox::valueChanged, this, &ShadingPanel::lightEdited);
    connect(m_elevation, &QSpinBox::valueChanged, this, &ShadingPanel::lightEdited);
    model::Document *doc = state->document();
    connect(doc, &model::Document::settingsChanged, this, &ShadingPanel::sync);
    connect(doc, &model::Document::documentReset, this, &ShadingPanel::sync);
    connect(doc, &model::Document::frameChanged, this, &ShadingPanel::sync);
    connect(doc, &model::Document::groupsChanged, this, &ShadingPanel::sync);
    connect(state, &EditorState::currentGroupChanged, this, &ShadingPanel::sync);
    connect(state, &EditorState::currentFrameChanged, this, &ShadingPanel::sync);
    sync();
}

void ShadingPanel::sync()
{
    const QSignalBlocker blockRamp(m_ramp), blockRim(m_rim), blockAzimuth(m_azimuth),
        blockElevation(m_elevation);
    const model::DocumentSettings &settings = m_state->document()->settings();
    m_azimuth->setValue(int(std::lround(settings.lightAzimuth)) % 360);
    m_elevation->setValue(int(std::lround(settings.lightElevation)));
    const model::StrokeGroup *group = m_state->currentGroup();
    const bool fills = group && !group->fills.empty();
    m_ramp->setEnabled(fills);
    m_rim->setEnabled(fills);
    const model::FillShading shading = fills ? group->fills.front().shading : model::FillShading();
    m_ramp->setCurrentIndex(std::max(0, m_ramp->findData(int(shading.ramp))));
    m_rim->setChecked(shading.rim);
    m_hint->setText(fills ? QString()
                          : tr("Fill regions of the current object with the Fill tool to shade "
                               "them."));
}

void ShadingPanel::shadingEdited()
{
    const model::StrokeGroup *group = m_state->currentGroup();
    if (!group)
        return;
    model::FillShading shading;
    shading.ramp = model::ShadeRamp(m_ramp->currentData().toInt());
    shading.rim = m_rim->isChecked();
    if (shading.rim && !shading.shaded()) // a rim alone shades: cel is the usual look
        shading.ramp = model::ShadeRamp::TwoTones;
    model::Document *doc = m_state->document();
    if (auto command = model::shadeFillsCommand(doc, group->id, shading))
        doc->undoStack()->push(command.release());
    sync();
}

void ShadingPanel::lightEdited()
{
    model::Document *doc = m_state->document();
    if (auto command = model::setLightCommand(doc, m_azimuth->value(), m_elevation->value()))
        doc->undoStack()->push(command.release());
}

} // namespace finbook::ui
