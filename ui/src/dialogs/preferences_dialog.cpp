#include <finbook/model/types.h>
#include <finbook/ui/dialogs/preferences_dialog.h>
#include <finbook/ui/dialogs/shortcut_editor.h>
#include <finbook/ui/timeline/onion_skin_editor.h>

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QMessageBox>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

namespace finbook::ui {

PreferencesDialog::PreferencesDialog(const Preferences &preferences,
                                     const ShortcutRegistry *shortcuts, QWidget *parent)
    : QDialog(parent)
    , m_onion(new OnionSkinEditor(this))
    , m_shortcuts(new ShortcutEditor(shortcuts, this))
{
    setWindowTitle(tr("Preferences"));
    setObjectName(QStringLiteral("preferencesDialog"));
    m_onion->setOnionSkin(preferences.onionSkin);
    auto *tabs = new QTabWidget(this);
    tabs->addTab(createGeneralPage(preferences), tr("New Documents"));
    tabs->addTab(m_onion, tr("Onion Skin"));
    tabs->addTab(m_shortcuts, tr("Keyboard Shortcuts"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &PreferencesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PreferencesDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(tabs);
    layout->addWidget(buttons);
    resize(720, 560);
}

QWidget *PreferencesDialog::createGeneralPage(const Preferences &preferences)
{
    auto *page = new QWidget(this);
    m_fps = new QSpinBox(page);
    m_fps->setRange(model::kMinFps, model::kMaxFps);
    m_fps->setSuffix(tr(" fps"));
    m_fps->setValue(preferences.frameRate);
    m_width = new QSpinBox(page);
    m_height = new QSpinBox(page);
    for (QSpinBox *box : {m_width, m_height}) {
        box->setRange(1, model::kMaxCanvasSide);
        box->setSuffix(tr(" px"));
    }
    m_width->setValue(preferences.canvasSize.width());
    m_height->setValue(preferences.canvasSize.height());
    m_autosave = new QSpinBox(page);
    m_autosave->setObjectName(QStringLiteral("autosaveMinutes"));
    m_autosave->setRange(0, 60);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setSpecialValueText(tr("Never"));
    m_autosave->setToolTip(tr("How often Finbook keeps a recovery copy of unsaved changes, "
                              "offered at the next start if Finbook did not close normally."));
    m_autosave->setValue(preferences.autosaveMinutes);
    auto *form = new QFormLayout(page);
    form->addRow(tr("Frame rate:"), m_fps);
    form->addRow(tr("Canvas width:"), m_width);
    form->addRow(tr("Canvas height:"), m_height);
    form->addRow(tr("Autosave every:"), m_autosave);
    return page;
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.onionSkin = m_onion->onionSkin();
    p.frameRate = m_fps->value();
    p.canvasSize = QSize(m_width->value(), m_height->value());
    p.autosaveMinutes = m_autosave->value();
    return p;
}

QMap<QString, QList<QKeySequence>> PreferencesDialog::shortcuts() const
{
    return m_shortcuts->shortcuts();
}

void PreferencesDialog::accept()
{
    if (m_shortcuts->hasConflicts()) {
        QMessageBox::warning(this, tr("Conflicting Shortcuts"),
                             tr("Two or more actions share a shortcut. Change or clear the "
                                "shortcuts marked in red, then press OK again."));
        return;
    }
    QDialog::accept();
}

} // namespace finbook::ui
