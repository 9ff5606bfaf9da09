#pragma once
// The sample's frame loop. Windowed and headless runs are the same loop over the same world
// and renderer; headless swaps the swapchain for an offscreen target and the window's input
// for nothing (later: a script), and never touches GLFW.
#include "options.h"

namespace sample {

// Runs the sample; returns the process exit code (non-zero when validation reported anything).
int run(Options options);

}  // namespace sample
