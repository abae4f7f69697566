#pragma once

#include <QUndoCommand>

namespace octaclay::app {

class ViewportWidget;

/// One stroke on the undo stack. The texels live in the viewport's core::EditHistory (which
/// keeps them compactly under a memory budget); this command only steps that history, so the
/// two stay in lockstep. A stroke the history dropped for its budget can no longer be undone:
/// undo() then does nothing and says so in text().
class StrokeCommand : public QUndoCommand {
public:
  StrokeCommand(ViewportWidget* viewport, const QString& label);
  void undo() override;
  void redo() override;

private:
  ViewportWidget* viewport_;
  bool done_ = true; // pushed after the stroke already ran
};

} // namespace octaclay::app
