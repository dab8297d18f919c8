// Asking before a rig edit throws a pose away (switching an object from pins to a cage or
// back, removing a posed rig).
#pragma once

#include <finbook/model/types.h>

class QWidget;

namespace finbook::ui {

// What the rig edit does: replaces the rig with another kind, or removes it (the question
// says which).
enum class RigChange { Replace, Remove };

// True when `group` has no pose to lose, or the user agrees to discard it. The question box
// is named "discardPosePrompt" so tests can answer it.
bool confirmDiscardingPose(QWidget *parent, const model::StrokeGroup &group,
                           RigChange change = RigChange::Replace);

} // namespace finbook::ui
