#pragma once

#include "octaclay/core/geometry/vec.h"

namespace octaclay::app {

class ViewportWidget;

// Runs the event loop for ms milliseconds, so that layouts, timers and redraws catch up.
void settleEvents(int ms);

// Waits up to 10 s for the viewport's GL context; false (with a message on stderr) when there is
// none or no document is open.
bool waitForViewport(ViewportWidget& view);

// Looks at the model's bounding-box centre along -towardEye, at the distance that fits the box,
// with the given screen up, then zooms by zoom.
void frameAlong(ViewportWidget& view, core::Vec3f towardEye, core::Vec3f up, double zoom);

} // namespace octaclay::app
