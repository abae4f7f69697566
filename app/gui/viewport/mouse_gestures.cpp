// The viewport's gestures and own keys (viewport_input.cpp), as Help ▸ Keyboard and Mouse lists
// them. Keep this table in step with the viewport: add a row with each new gesture or key.

#include "mouse_gestures.h"

#include <QCoreApplication>

namespace octaclay::app {

QList<Gesture> viewportGestures() {
  const auto tr = [](const char* text) {
    return QCoreApplication::translate("octaclay::app::Gesture", text);
  };
  return {
      {tr("Left-drag on the model"), tr("Sculpt or paint with the chosen brush")},
      {tr("Ctrl + left-drag"), tr("Sculpt inverted (push ↔ pull)")},
      {tr("Shift + left-drag"), tr("Smooth")},
      {tr("Right-drag or middle-drag"), tr("Orbit the view")},
      {tr("Left-drag off the model (or Alt + left-drag)"), tr("Orbit the view")},
      {tr("Alt + click on another object"),
       tr("Edit that object (undo still reaches every object's steps)")},
      {tr("Left-drag an arrow (Object Mode)"), tr("Move the object along that axis")},
      {tr("Left-drag the white ring (Object Mode)"), tr("Scale the object")},
      {tr("Shift + middle-drag or Ctrl + right-drag"), tr("Pan the view")},
      {tr("Shift + left-drag off the model"), tr("Pan the view")},
      {tr("Mouse wheel"), tr("Zoom")},
      {tr("[ and ]"), tr("Brush radius smaller / larger")},
      {tr("Shift + [ and Shift + ]"), tr("Brush strength weaker / stronger")},
      {tr("Pen pressure"), tr("Scales strength or radius (Brushes dock, Pressure)")},
  };
}

} // namespace octaclay::app
