// What the Analyses dock says under a result when the window's action is no longer the one the
// result ran on: a setting moved since Run (the result is the old setting's), another action or
// preset opened, parts left out or put back.
#pragma once

#include <QString>

#include "model/action_model.h"

namespace pat::ui {

/// Empty when `window` is the action `ran_on` with the same settings (as the regulation panel
/// shows them, to 0.01 mm); otherwise one sentence naming what differs ("Since this ran: let-off
/// 0.00 → +0.50 mm. Press Run to see the window's settings."). With `settings_matter` false (an
/// analysis no setting changes) only another action or preset is named.
QString settings_moved_note(const ActionModel& ran_on, const ActionModel& window,
                            bool settings_matter = true);

}  // namespace pat::ui
