#include "replace_document_command.h"

namespace octaclay::app {

ReplaceDocumentCommand::ReplaceDocumentCommand(const QString& text,
                                               std::unique_ptr<HeldDocument> other, Swap swap)
    : QUndoCommand(text), other_(std::move(other)), swap_(std::move(swap)) {}

void ReplaceDocumentCommand::undo() {
  swap_(*other_);
  done_ = false;
}

void ReplaceDocumentCommand::redo() {
  if (done_) return; // QUndoStack::push() calls redo(); the new document is already shown
  swap_(*other_);
  done_ = true;
}

} // namespace octaclay::app
