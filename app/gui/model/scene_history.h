#pragma once

// The scene's one history (issue 33): strokes, operations and replaced documents of every
// object, and the scene's own steps (scene_step.h), in the order they were made, under one
// memory budget. Qt-free; GUI thread.

#include "scene_step.h"

#include "octaclay/core/document/edit_history.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>

namespace octaclay::app {

/// One linear history across the scene, as Blender's and Nomad's: each entry is either a step
/// of an object's document or a SceneStep. Each object keeps its own core::EditHistory (its
/// document's steps, its N): the edited object's is the SculptSession's (`live`), the others'
/// are parked here while they are not edited (leave, enter), so switching objects clears
/// nothing. A new entry anywhere clears every redo entry (and the redo steps of every object's
/// history); the budget drops the oldest entries, whichever object they belong to. The
/// histories' own budgets are lifted: only this one drops.
class SceneHistory {
public:
  struct Entry {
    std::uint64_t serial = 0;         ///< unique over the history's life, never 0
    ObjectId object = 0;              ///< a document step's object
    std::unique_ptr<SceneStep> scene; ///< a scene step; null for a document step
  };

  /// live: the edited object's history (the session's), which must outlive this.
  explicit SceneHistory(core::EditHistory& live, std::size_t budgetBytes = std::size_t{256} << 20);

  /// Drops every entry and every object's history (the live one too); object `live` is edited.
  void restart(ObjectId live);
  /// Drops every entry and every object's history; the same object stays edited.
  void clear() { restart(liveId_); }
  /// The object whose history is the live one.
  ObjectId liveObject() const { return liveId_; }
  /// Parks the live history under liveObject(), leaving the live one empty (a document is about
  /// to be uploaded, which clears it).
  void leave();
  /// Object id's parked history (empty when it has none) becomes the live one.
  void enter(ObjectId id);

  /// Takes in a step the live history recorded since the last call (a stroke, an operation, a
  /// replaced document) as the newest entry; returns whether there was one.
  bool noteLiveStep();
  /// Adds a scene step, done, as the newest entry.
  void record(SceneStep step);

  bool canUndo() const { return cursor_ > 0; }
  bool canRedo() const { return cursor_ < entries_.size(); }
  std::size_t undoCount() const { return cursor_; }
  std::size_t redoCount() const { return entries_.size() - cursor_; }
  /// Entry k (0 the oldest kept), or nullptr past the end.
  const Entry* entryAt(std::size_t k) const { return k < entries_.size() ? &entries_[k] : nullptr; }
  /// Entry k's document step (held by its object's history), or nullptr for a scene step.
  const core::EditStep* documentStepAt(std::size_t k) const;
  /// The entries undo and redo would take, or nullptr.
  Entry* nextUndoEntry() { return canUndo() ? &entries_[cursor_ - 1] : nullptr; }
  Entry* nextRedoEntry() { return canRedo() ? &entries_[cursor_] : nullptr; }
  /// The document step undo would revert, or nullptr (none, or a scene step).
  const core::EditStep* nextUndo() const {
    return canUndo() ? documentStepAt(cursor_ - 1) : nullptr;
  }
  /// The next undo (undo) or redo entry was taken by the caller: the cursor moves over it.
  void stepped(bool undo);

  /// Memory held: every object's history and every scene step.
  std::size_t bytes() const;
  std::size_t budget() const { return budget_; }
  /// A new budget: the oldest undo entries drop while bytes() exceeds it, never the newest
  /// one and never a redo entry.
  void setBudget(std::size_t budgetBytes);
  /// Entries the budget dropped since the last restart.
  std::size_t dropped() const { return dropped_; }
  /// The serial of the entry undo would take (0: none, as opened or made; kUnreachable: none,
  /// older entries dropped): a state to compare with a saved one.
  std::uint64_t position() const;
  static constexpr std::uint64_t kUnreachable = core::EditHistory::kUnreachable;

private:
  core::EditHistory& historyOf(ObjectId id);
  const core::EditHistory* findHistory(ObjectId id) const;
  void push(Entry entry);
  void clearRedo();
  void trim();
  void forgetEmptyHistories();

  core::EditHistory& live_;
  ObjectId liveId_ = 0;
  std::uint64_t livePosition_ = 0;               // live_.position() as last taken in
  std::map<ObjectId, core::EditHistory> parked_; // the other objects'
  std::deque<Entry> entries_; // oldest first; [0, cursor_) undoable, [cursor_, end) redoable
  std::size_t cursor_ = 0;
  std::size_t budget_;
  std::size_t dropped_ = 0;
  std::uint64_t serials_ = 0;
};

} // namespace octaclay::app
