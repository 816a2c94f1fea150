#pragma once
/// \file window_loop.hpp
/// The windowed studio: a GLFW window, its input queued in the order it came, and frames drawn
/// on events and while work is pending (idle, it waits for events and draws nothing).

#include "state/app_state.hpp"

namespace pagor::studio {

/// Opens the window on `state` and runs until it is closed; throws Error when no window can be
/// opened. Returns the exit code.
int run_window(AppState state);

}  // namespace pagor::studio
