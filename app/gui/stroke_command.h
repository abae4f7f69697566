#pragma once

#include <QUndoCommand>

namespace octaclay::app {

class ViewportWidget;

/// One step of the viewport's history (a stroke, or a whole-document change such as Even Out
/// Samples) on the undo stack. The texels live in the viewport's core::EditHistory (which
/// keeps them compactly under a memory budget); this command only steps that history, so the
/// two stay in lockstep. A step the history dropped for its budget can no longer be undone:
/// undo() then does nothing and says so in text().
class StrokeCommand : public QUndoCommand {
public:
  /// text: what Edit ▸ Undo names, e.g. "Stroke (push)"; the step is already in the history.
  StrokeCommand(ViewportWidget* viewport, const QString& text);
  void undo() override;
  void redo() override;

private:
  ViewportWidget* viewport_;
  bool done_ = true; // pushed after the stroke already ran
};

} // namespace octaclay::app
