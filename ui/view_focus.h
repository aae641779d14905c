// What the action view frames: the whole action or a close-up a teacher points at
// (ActionView::set_focus; `pianoaction --view`).
#pragma once

namespace pat::ui {

enum class ViewFocus { whole, escapement, checking };

}  // namespace pat::ui
