// The budgeted undo history: a linear stack of EditSteps (edit_step.cpp holds their encoding).

#include "octaclay/core/document/edit_history.h"

#include "document/edit_checks.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/error.h"

#include <string>
#include <utility>

namespace octaclay::core {

using detail::editLayerName;
using detail::invalidEdit;
using detail::texelArea;

// ---------------------------------------------------------------------------------------------
// EditHistory

namespace {

// An EditStep can be built by hand: check that applying it cannot read or write out of bounds.
void validateStroke(const EditStep& s) {
  if (s.imageSide < 2)
    invalidEdit("EditHistory::record: the stroke has image side " + std::to_string(s.imageSide) +
                "; build strokes with EditStepRecorder");
  std::size_t changed = 0;
  for (const TileChange& t : s.tiles) {
    const TexelRect expected = EditStepRecorder::tileRegion(
        s.imageSide, s.imageRows == 0 ? s.imageSide : s.imageRows, t.tileX, t.tileY);
    if (t.region != expected || t.channels != editLayerChannels(t.layer))
      invalidEdit("EditHistory::record: tile (" + std::to_string(t.tileX) + ", " +
                  std::to_string(t.tileY) +
                  ") has a region or channel count that does not match its layer and image; build "
                  "strokes with EditStepRecorder");
    std::size_t covered = 0, count = 0;
    for (std::size_t r = 0; r + 1 < t.runs.size(); r += 2) {
      covered += std::size_t{t.runs[r]} + t.runs[r + 1];
      count += t.runs[r + 1];
    }
    const std::size_t c = static_cast<std::size_t>(t.channels);
    if (t.runs.size() % 2 != 0 || covered > texelArea(t.region) || count != t.changedTexels ||
        t.before.size() != count * c || t.xorBits.size() != count * c)
      invalidEdit("EditHistory::record: tile (" + std::to_string(t.tileX) + ", " +
                  std::to_string(t.tileY) +
                  ") has an inconsistent payload; build strokes with EditStepRecorder");
    changed += count;
  }
  if (changed != s.changedTexels)
    invalidEdit("EditHistory::record: the stroke's changedTexels does not match its tiles");
}

} // namespace

EditHistory::EditHistory(std::size_t budgetBytes) : budget_(budgetBytes) {}

void EditHistory::record(EditStep stroke) {
  const bool replaces = stroke.replacesDocument();
  if (stroke.tiles.empty() && !replaces) return;
  if (replaces) {
    if (!stroke.replacedAfter || !stroke.tiles.empty())
      invalidEdit("EditHistory::record: a step replacing the document needs both documents and "
                  "no tiles");
    const int before = stroke.replacedBefore->size() + 1;
    if (side_ != 0 && before != side_)
      invalidEdit("EditHistory::record: the replaced document has side " + std::to_string(before) +
                  " but the history's document has side " + std::to_string(side_));
    stroke.imageSide = stroke.replacedAfter->size() + 1;
    const int rows = stroke.replacedAfter->positions.rows();
    stroke.imageRows = rows == stroke.imageSide ? 0 : rows;
  } else {
    validateStroke(stroke);
    if (side_ != 0 && side_ != stroke.imageSide)
      invalidEdit("EditHistory::record: the stroke is for an image of side " +
                  std::to_string(stroke.imageSide) + " but the history holds strokes for side " +
                  std::to_string(side_) + "; clear() the history first");
  }
  stroke.bytes = stroke.computeBytes();
  stroke.serial = ++serials_;
  clearRedo();
  bytes_ += stroke.bytes;
  side_ = stroke.imageSide;
  steps_.push_back(std::move(stroke));
  cursor_ = steps_.size();
  while (bytes_ > budget_ && steps_.size() > 1)
    dropOldest();
}

void EditHistory::dropOldest() {
  if (cursor_ == 0) return;
  bytes_ -= steps_.front().bytes;
  steps_.pop_front();
  --cursor_;
  ++dropped_;
}

void EditHistory::clearRedo() {
  while (steps_.size() > cursor_) {
    bytes_ -= steps_.back().bytes;
    steps_.pop_back();
  }
}

void EditHistory::setBudget(std::size_t budgetBytes) {
  budget_ = budgetBytes;
  while (bytes_ > budget_ && cursor_ > 1)
    dropOldest();
}

std::uint64_t EditHistory::position() const {
  if (cursor_ > 0) return steps_[cursor_ - 1].serial;
  return dropped_ > 0 ? kUnreachable : 0;
}

const EditStep* EditHistory::nextUndo() const {
  return canUndo() ? &steps_[cursor_ - 1] : nullptr;
}

const EditStep* EditHistory::nextRedo() const {
  return canRedo() ? &steps_[cursor_] : nullptr;
}

const EditStep* EditHistory::undo(const TileApplier& apply, const DocumentReplacer& replace) {
  if (!canUndo()) return nullptr;
  const EditStep& s = steps_[cursor_ - 1];
  if (s.replacesDocument()) {
    if (!replace) invalidEdit("EditHistory::undo: the step replaced the document: no replacer");
    replace(*s.replacedBefore);
    side_ = s.replacedBefore->size() + 1;
  }
  for (auto it = s.tiles.rbegin(); it != s.tiles.rend(); ++it)
    it->apply(TileState::Before, apply);
  --cursor_;
  return &s;
}

const EditStep* EditHistory::redo(const TileApplier& apply, const DocumentReplacer& replace) {
  if (!canRedo()) return nullptr;
  const EditStep& s = steps_[cursor_];
  if (s.replacesDocument()) {
    if (!replace) invalidEdit("EditHistory::redo: the step replaced the document: no replacer");
    replace(*s.replacedAfter);
    side_ = s.imageSide;
  }
  for (const TileChange& t : s.tiles)
    t.apply(TileState::After, apply);
  ++cursor_;
  return &s;
}

void EditHistory::clear() {
  steps_.clear();
  cursor_ = 0;
  bytes_ = 0;
  dropped_ = 0;
  side_ = 0;
}

} // namespace octaclay::core
