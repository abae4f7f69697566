#pragma once

class QMenu;

namespace octaclay::app {

class ViewportWidget;

/// Adds the looks to the View menu: Material (Lit, then each matcap; one at a time), Wireframe
/// (the displayed level's edges) and Background… (a colour or a top-to-bottom gradient). Applies
/// the looks saved in QSettings to viewport now, and saves every change.
void addLookActions(QMenu* view, ViewportWidget* viewport);

} // namespace octaclay::app
