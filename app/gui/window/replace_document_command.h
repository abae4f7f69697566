#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"

#include <QString>
#include <QUndoCommand>

#include <functional>
#include <memory>

namespace octaclay::app {

/// A whole document with what goes with it: its stroke history and where it came from.
struct HeldDocument {
  core::Document document;
  core::EditHistory history;
  QString path;         ///< its file, empty if never saved
  QString importedFrom; ///< the mesh it was imported from, if it was
  bool forceModified = false;
};

/// A step that replaced the document with another, e.g. File ▸ Import Mesh, which may change N:
/// it holds the document that is not shown (before the step: the one replaced; after undo: the
/// one the step made) with its stroke history, and undo and redo swap it with the viewport's.
/// The strokes on either side stay undoable, since each document keeps its own history.
/// Memory: one extra document and its history, for as long as the step is on the stack.
class ReplaceDocumentCommand : public QUndoCommand {
public:
  /// Swaps the held document with the shown one; false if the viewport refused it (the held one
  /// is then unchanged and the shown one stays).
  using Swap = std::function<bool(HeldDocument& held)>;

  /// other: the document replaced; the new one is already shown (push() does nothing more).
  ReplaceDocumentCommand(const QString& text, std::unique_ptr<HeldDocument> other, Swap swap);
  void undo() override;
  void redo() override;

private:
  std::unique_ptr<HeldDocument> other_;
  Swap swap_;
  bool done_ = true;
};

} // namespace octaclay::app
