#pragma once

#include "octaclay/core/geometry/vec.h"

#include <QImage>

class QWidget;

namespace octaclay::app {

class ViewportWidget;

// Runs the event loop for ms milliseconds, so that layouts, timers and redraws catch up.
void settleEvents(int ms);

// Waits up to 10 s for the viewport's GL context; false (with a message on stderr) when there is
// none or no document is open.
bool waitForViewport(ViewportWidget& view);

// The window as on screen: QWidget::grab() with the viewport's frame and the labels over it
// painted in (the frame is a native GL window's, which grab() does not see).
QImage grabWithViewport(QWidget& window, ViewportWidget& view);

// Looks at the model's bounding-box centre along -towardEye, at the distance that fits the box,
// with the given screen up, then zooms by zoom.
void frameAlong(ViewportWidget& view, core::Vec3f towardEye, core::Vec3f up, double zoom);

} // namespace octaclay::app
