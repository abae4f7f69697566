#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <Qt>

#include <string>
#include <vector>

class QFrame;
class QTreeWidget;
class QVBoxLayout;

namespace octaclay::app {

/// The item data role of the brush list holding a brush's id (category headers have none).
inline constexpr int kBrushIdRole = Qt::UserRole;

/// Fills tree with the brushes grouped by category (Sculpt, Paint, Splat in that order, each
/// under a bold header, brushes in the order given), shown by name, with their description and
/// folder as tooltip and their id as kBrushIdRole data. Emits no signal of tree's.
void fillBrushTree(QTreeWidget& tree, const std::vector<gpu::BrushManifest>& brushes);

/// Replaces what layout shows with a heading and one selectable, wrapping label per error
/// (object name "brushError", the full text in property "error"); frame is shown only when
/// there are errors.
void showBrushErrors(QFrame& frame, QVBoxLayout& layout, const std::vector<std::string>& errors);

} // namespace octaclay::app
