#include "stroke_command.h"

#include "modeller.h"
#include "viewport_widget.h"

#include "octaclay/core/document/edit_history.h"

#include <QUndoStack>

#include <vector>

namespace octaclay::app {

StrokeCommand::StrokeCommand(ViewportWidget* viewport, const QString& text)
    : QUndoCommand(text), viewport_(viewport) {}

void StrokeCommand::undo() {
  if (!dropped_ && !viewport_->modeller().undoStroke()) markDropped();
  done_ = false;
}

void StrokeCommand::redo() {
  if (done_) return; // QUndoStack::push() calls redo(); the stroke is already on the model
  if (!dropped_) viewport_->modeller().redoStroke();
  done_ = true;
}

void StrokeCommand::markDropped() {
  if (dropped_) return;
  dropped_ = true;
  setText(text() + QObject::tr(" — dropped from history"));
}

int markDroppedSteps(QUndoStack& stack, const core::EditHistory& history) {
  // The steps done on the shown document: the StrokeCommands after the last step that is not
  // one (a document replaced), each done one a step of history unless it was dropped.
  std::vector<StrokeCommand*> done;
  for (int k = stack.index() - 1; k >= 0; --k) {
    auto* step = dynamic_cast<StrokeCommand*>(const_cast<QUndoCommand*>(stack.command(k)));
    if (!step) break;
    done.push_back(step); // newest first
  }
  const std::size_t kept = history.undoCount();
  int marked = 0;
  for (std::size_t k = kept; k < done.size(); ++k)
    if (!done[k]->dropped()) {
      done[k]->markDropped();
      ++marked;
    }
  return marked;
}

bool oldestStepDropped(const QUndoStack& stack) {
  const auto* first =
      stack.count() > 0 ? dynamic_cast<const StrokeCommand*>(stack.command(0)) : nullptr;
  return first && first->dropped();
}

} // namespace octaclay::app
