#pragma once

// The undo history (DESIGN.md, "Brushes": the engine records what each stroke changed, tiles
// before and after): a linear stack of EditSteps (edit_step.h, their encoding) under a memory
// budget, handing the texels back through a TileApplier (a GPU upload, or applierFor() on a
// CPU image). CPU only.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_step.h"
#include "octaclay/core/geometry/geometry_image.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>

namespace octaclay::core {

/// Linear undo/redo history of edit steps (strokes, operations) under a memory budget. Not
/// thread-safe: call it from the thread that owns the document.
class EditHistory {
public:
  /// Shows a whole document a replacing step brings back (undo: its before, redo: its after).
  /// Throws to leave the history unchanged.
  using DocumentReplacer = std::function<void(const Document&)>;

  /// budgetBytes: most memory the history may hold (see bytes()); default 256 MiB.
  explicit EditHistory(std::size_t budgetBytes = std::size_t{256} << 20);

  /// Adds step as the newest undo step and clears the redo steps (a step replacing the document,
  /// EditStep::replacesDocument, counts as one; its before must be the shown document's size).
  /// Then, while bytes() exceeds the budget, drops the oldest steps, never step itself (alone over
  /// budget, it is kept and everything older is dropped). A step with no tiles is ignored. Throws
  /// Error(InvalidArgument) if step.imageSide differs from the steps held (clear() first).
  void record(EditStep step);

  bool canUndo() const { return cursor_ > 0; }
  bool canRedo() const { return cursor_ < steps_.size(); }
  std::size_t undoCount() const { return cursor_; }
  std::size_t redoCount() const { return steps_.size() - cursor_; }
  /// Step k of those held (0 the oldest kept), done or undone; nullptr past the end.
  const EditStep* stepAt(std::size_t k) const { return k < steps_.size() ? &steps_[k] : nullptr; }
  /// The step undo() would revert, or nullptr.
  const EditStep* nextUndo() const;
  /// The step redo() would reapply, or nullptr.
  const EditStep* nextRedo() const;

  /// Reverts the newest step: apply receives every changed texel's `before` (tiles in reverse
  /// recording order). The target must hold the step's `after` state. Returns the step (valid
  /// until the next record(), clear() or destruction), or nullptr if there is nothing to undo.
  /// If apply throws, the history is unchanged and the exception propagates.
  const EditStep* undo(const TileApplier& apply, const DocumentReplacer& replace = {});
  /// Reapplies the newest undone step: apply receives every changed texel's `after`. Same
  /// contract as undo().
  const EditStep* redo(const TileApplier& apply, const DocumentReplacer& replace = {});

  /// Memory held in bytes: per step its struct, label and tile array, per tile its struct and
  /// compressed payload (capacities, not sizes).
  std::size_t bytes() const { return bytes_; }
  std::size_t budget() const { return budget_; }
  /// A new budget (Edit ▸ Preferences): while bytes() exceeds it, drops the oldest undo steps,
  /// never the newest one and never a redo step.
  void setBudget(std::size_t budgetBytes);
  /// Drops every step.
  void clear();
  /// Drops the oldest step, which must be undoable (canUndo()), whatever the budget: a history
  /// of several documents (the modeller's scene) keeps one budget over all of them and drops
  /// its oldest step wherever it is. Counts in dropped(). Nothing happens without an undoable
  /// step.
  void dropOldest();
  /// Drops every redo step (a new step somewhere else in a history of several documents).
  void clearRedo();
  /// Steps the budget dropped since the last clear().
  std::size_t dropped() const { return dropped_; }
  /// The serial of the step undo() would revert (0: none, the document as opened or made;
  /// kUnreachable: none, older steps dropped): a state to compare with a saved one.
  std::uint64_t position() const;
  static constexpr std::uint64_t kUnreachable = ~std::uint64_t{0};

private:
  std::size_t budget_;
  std::size_t bytes_ = 0;
  std::deque<EditStep> steps_; // oldest first; [0, cursor_) undoable, [cursor_, end) redoable
  std::size_t cursor_ = 0;
  std::size_t dropped_ = 0;
  std::uint64_t serials_ = 0;
  int side_ = 0; // N+1 of the document at the cursor (0: not known yet)
};

/// A TileApplier writing Positions tiles into image (4 floats per texel, bits copied as they
/// are). The image must outlive the applier. The applier throws Error(InvalidArgument) for
/// another layer or a region outside the image.
TileApplier applierFor(GeometryImage& image);

/// A TileApplier writing any layer into doc; a uniform layer is first filled out to texels
/// (and the mask marked present when written). The document must outlive the applier. Throws
/// Error(InvalidArgument) for a region outside the image.
TileApplier applierFor(Document& doc);

} // namespace octaclay::core
