#include "stroke_command.h"

#include "viewport_widget.h"

namespace octaclay::app {

StrokeCommand::StrokeCommand(ViewportWidget* viewport, const QString& text)
    : QUndoCommand(text), viewport_(viewport) {}

void StrokeCommand::undo() {
  if (!viewport_->undoStroke()) setText(text() + QObject::tr(" — dropped from history"));
  done_ = false;
}

void StrokeCommand::redo() {
  if (done_) return; // QUndoStack::push() calls redo(); the stroke is already on the model
  viewport_->redoStroke();
  done_ = true;
}

} // namespace octaclay::app
