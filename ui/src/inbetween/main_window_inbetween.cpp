// Frame → Generate In-betweens…: the dialog with its live preview in the canvas, then one
// InsertInbetweensCommand.
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/ui/canvas_widget.h>
#include <finbook/ui/deform_actions.h>
#include <finbook/ui/editor_state.h>
#include <finbook/ui/inbetween/inbetween_dialog.h>
#include <finbook/ui/main_window.h>

namespace finbook::ui {

void MainWindow::generateInbetweens(model::Id firstKey, model::Id secondKey)
{
    deform::ArapOptions options;
    if (m_deform)
        options.extraPasses = m_deform->controller()->extraPasses(); // preview as it will solve
    InbetweenDialog dialog(
        m_doc, firstKey, secondKey, options,
        [this](std::optional<model::Frame> frame) { m_canvas->setPreviewFrame(std::move(frame)); },
        this);
    dialog.setObjectName(QStringLiteral("inbetweenDialog"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    auto *command = new model::InsertInbetweensCommand(m_doc, dialog.firstKey(), dialog.secondKey(),
                                                       dialog.count(), dialog.options());
    const bool obsolete = command->isObsolete();
    m_doc->undoStack()->push(command);
    if (!obsolete)
        m_state->setCurrentFrameIndex(m_doc->frameIndex(dialog.firstKey()));
}

} // namespace finbook::ui
