#pragma once

#include <QUndoCommand>

class QUndoStack;

namespace octaclay::core {
class EditHistory;
}

namespace octaclay::app {

class ViewportWidget;

/// One step of the viewport's history (a stroke, or a whole-document change such as Even Out
/// Samples) on the undo stack. The texels live in the viewport's core::EditHistory (which
/// keeps them compactly under a memory budget); this command only steps that history, so the
/// two stay in lockstep. A step the history dropped for its budget can no longer be undone:
/// it is marked (markDropped, "— dropped from history" in its text) and undo() does nothing.
class StrokeCommand : public QUndoCommand {
public:
  /// text: what Edit ▸ Undo names, e.g. "Stroke (push)"; the step is already in the history.
  StrokeCommand(ViewportWidget* viewport, const QString& text);
  void undo() override;
  void redo() override;

  void markDropped();
  bool dropped() const { return dropped_; }

private:
  ViewportWidget* viewport_;
  bool done_ = true; // pushed after the stroke already ran
  bool dropped_ = false;
};

/// Marks the StrokeCommands of stack whose steps history (the shown document's) no longer
/// holds: the oldest of those done since the last step that replaced the document. Returns how
/// many it marked now (0 when they were marked already or none were dropped).
int markDroppedSteps(QUndoStack& stack, const core::EditHistory& history);

/// Whether the oldest step of stack was dropped from its history: the state before it, the
/// model as opened or made, can no longer be reached.
bool oldestStepDropped(const QUndoStack& stack);

} // namespace octaclay::app
