#pragma once

#include <QList>
#include <QString>

namespace octaclay::app {

/// One thing the viewport does on a mouse gesture or a key it handles itself (not a QAction),
/// as Help ▸ Keyboard and Mouse lists it.
struct Gesture {
  QString input;  ///< e.g. "Ctrl + left-drag"
  QString action; ///< e.g. "Sculpt inverted (push ↔ pull)"
};

/// Every gesture and viewport key, in the order the sheet lists them. One table in
/// mouse_gestures.cpp: whoever teaches the viewport a new gesture or key adds its row there.
QList<Gesture> viewportGestures();

} // namespace octaclay::app
