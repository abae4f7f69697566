#include "scene_history.h"

#include <limits>
#include <utility>

namespace octaclay::app {
namespace {

// The histories inside never drop on their own: the scene's budget drops across them.
constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

} // namespace

SceneHistory::SceneHistory(core::EditHistory& live, std::size_t budgetBytes)
    : live_(live), budget_(budgetBytes) {
  live_.setBudget(kUnbounded);
}

void SceneHistory::restart(ObjectId live) {
  entries_.clear();
  parked_.clear();
  live_.clear();
  live_.setBudget(kUnbounded);
  liveId_ = live;
  livePosition_ = live_.position();
  cursor_ = 0;
  dropped_ = 0;
}

void SceneHistory::leave() {
  core::EditHistory parked(kUnbounded);
  std::swap(parked, live_);
  if (parked.undoCount() + parked.redoCount() > 0)
    parked_.insert_or_assign(liveId_, std::move(parked));
  live_.setBudget(kUnbounded);
}

void SceneHistory::enter(ObjectId id) {
  core::EditHistory next(kUnbounded);
  if (const auto at = parked_.find(id); at != parked_.end()) {
    next = std::move(at->second);
    parked_.erase(at);
  }
  std::swap(next, live_);
  liveId_ = id;
  livePosition_ = live_.position();
}

bool SceneHistory::noteLiveStep() {
  const std::uint64_t now = live_.position();
  if (now == livePosition_ || live_.redoCount() != 0 || live_.undoCount() == 0) {
    livePosition_ = now;
    return false;
  }
  livePosition_ = now;
  Entry entry;
  entry.object = liveId_;
  push(std::move(entry));
  return true;
}

void SceneHistory::record(SceneStep step) {
  Entry entry;
  entry.scene = std::make_unique<SceneStep>(std::move(step));
  push(std::move(entry));
}

void SceneHistory::push(Entry entry) {
  clearRedo();
  entry.serial = ++serials_;
  entries_.push_back(std::move(entry));
  cursor_ = entries_.size();
  trim();
}

void SceneHistory::stepped(bool undo) {
  if (undo ? !canUndo() : !canRedo()) return;
  cursor_ = undo ? cursor_ - 1 : cursor_ + 1;
  livePosition_ = live_.position();
}

void SceneHistory::clearRedo() {
  for (std::size_t k = cursor_; k < entries_.size(); ++k)
    if (!entries_[k].scene) historyOf(entries_[k].object).clearRedo();
  entries_.erase(entries_.begin() + std::ptrdiff_t(cursor_), entries_.end());
  forgetEmptyHistories();
}

void SceneHistory::trim() {
  while (bytes() > budget_ && cursor_ > 1) {
    Entry& oldest = entries_.front();
    if (!oldest.scene) historyOf(oldest.object).dropOldest();
    entries_.pop_front();
    --cursor_;
    ++dropped_;
  }
  forgetEmptyHistories();
}

void SceneHistory::setBudget(std::size_t budgetBytes) {
  budget_ = budgetBytes;
  trim();
}

void SceneHistory::forgetEmptyHistories() {
  // A parked history without steps holds nothing an entry could need.
  for (auto at = parked_.begin(); at != parked_.end();)
    at = at->second.undoCount() + at->second.redoCount() == 0 ? parked_.erase(at) : std::next(at);
}

core::EditHistory& SceneHistory::historyOf(ObjectId id) {
  if (id == liveId_) return live_;
  const auto [at, added] = parked_.try_emplace(id, kUnbounded);
  return at->second;
}

const core::EditHistory* SceneHistory::findHistory(ObjectId id) const {
  if (id == liveId_) return &live_;
  const auto at = parked_.find(id);
  return at == parked_.end() ? nullptr : &at->second;
}

const core::EditStep* SceneHistory::documentStepAt(std::size_t k) const {
  if (k >= entries_.size() || entries_[k].scene) return nullptr;
  const ObjectId id = entries_[k].object;
  const core::EditHistory* history = findHistory(id);
  if (!history) return nullptr;
  // An object's document steps are its entries, in the same order.
  std::size_t before = 0;
  for (std::size_t e = 0; e < k; ++e)
    before += !entries_[e].scene && entries_[e].object == id;
  return history->stepAt(before);
}

std::size_t SceneHistory::bytes() const {
  std::size_t total = live_.bytes();
  for (const auto& [id, history] : parked_)
    total += history.bytes();
  for (const Entry& e : entries_)
    total += sizeof(Entry) + (e.scene ? e.scene->bytes() : 0);
  return total;
}

std::uint64_t SceneHistory::position() const {
  if (cursor_ > 0) return entries_[cursor_ - 1].serial;
  return dropped_ > 0 ? kUnreachable : 0;
}

} // namespace octaclay::app
