#include "rig_prompt.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace finbook::ui {

namespace {
struct RigPrompt {
    Q_DECLARE_TR_FUNCTIONS(RigPrompt)
};
} // namespace

bool confirmDiscardingPose(QWidget *parent, const model::StrokeGroup &group, RigChange change)
{
    if (!group.rig.isPosed())
        return true;
    const QString text =
        change == RigChange::Remove
            ? RigPrompt::tr("\"%1\" is posed. Removing its rig sends the drawing back to "
                            "rest. (Apply Pose to Drawing first keeps the pose.)")
            : RigPrompt::tr("\"%1\" is posed. Replacing its rig sends the drawing back to "
                            "rest. (Apply Pose to Drawing first keeps the pose.)");
    QMessageBox box(QMessageBox::Question, RigPrompt::tr("Discard the Pose?"), text.arg(group.name),
                    QMessageBox::Discard | QMessageBox::Cancel, parent);
    box.setObjectName(QStringLiteral("discardPosePrompt"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Discard;
}

} // namespace finbook::ui
