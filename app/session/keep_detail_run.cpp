#include "keep_detail_run.h"

#include "octaclay/core/document/edit_steps.h"
#include "octaclay/core/relax/relax.h"

#include <algorithm>
#include <cmath>

namespace octaclay::app {
namespace {

// Calls visit(index) with the texel index ((W+1)×(H+1), row-major) of every position the step
// changed.
template <typename Visit>
void forEachChangedPosition(const core::EditStep& step, std::size_t side, Visit&& visit) {
  for (const core::TileChange& t : step.tiles) {
    if (t.layer != core::EditLayer::Positions) continue;
    const std::size_t x = static_cast<std::size_t>(t.region.x),
                      y = static_cast<std::size_t>(t.region.y),
                      width = static_cast<std::size_t>(t.region.width);
    std::size_t at = 0;
    for (std::size_t r = 0; r + 1 < t.runs.size(); r += 2) {
      at += t.runs[r];
      for (std::size_t k = 0; k < t.runs[r + 1]; ++k, ++at)
        visit((y + at / width) * side + x + at % width);
    }
  }
}

// The samples a stroke changed in the positions, to the texel ((W+1)×(H+1), row-major): the
// relaxation after it reaches keepDetailMargin samples beyond them and no farther.
std::vector<std::uint8_t> changedSamples(const core::EditStep& record, int side, int rows) {
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(side) * static_cast<std::size_t>(rows),
                                    0);
  bool any = false;
  forEachChangedPosition(record, static_cast<std::size_t>(side), [&](std::size_t index) {
    changed[index] = 1;
    any = true;
  });
  if (!any) changed.clear();
  return changed;
}

// Keep-detail's first relaxation during a dragging stroke (snake hook), after this many dabs.
constexpr int kFirstRelaxationDab = 4;

core::RelaxOptions pinOptions(const std::vector<std::array<float, 2>>& pinnedPath,
                              const core::GeometryImage& image) {
  core::RelaxOptions options;
  for (const auto& uv : pinnedPath)
    options.pinned.push_back(
        {static_cast<int>(std::lround(uv[0] * static_cast<float>(image.width()))),
         static_cast<int>(std::lround(uv[1] * static_cast<float>(image.height())))});
  return options;
}

// Adds to dabChanged ((W+1)×(H+1), allocated on first use) the samples the dabs changed: those
// `soFar` (the stroke's record so far) changed, except where a relaxation left them (`relaxed`)
// and no dab moved them since. Returns whether any is marked.
bool addDabChanges(std::vector<std::uint8_t>& dabChanged,
                   const std::unordered_map<std::size_t, core::Vec4f>& relaxed,
                   const core::EditStep& soFar, const core::GeometryImage& positions) {
  const std::size_t side = static_cast<std::size_t>(positions.side());
  if (dabChanged.empty()) dabChanged.assign(side * static_cast<std::size_t>(positions.rows()), 0);
  forEachChangedPosition(soFar, side, [&](std::size_t index) {
    if (dabChanged[index]) return;
    const auto left = relaxed.find(index);
    if (left == relaxed.end() || !(left->second == positions.texels()[index]))
      dabChanged[index] = 1;
  });
  return std::find(dabChanged.begin(), dabChanged.end(), 1) != dabChanged.end();
}

// Notes where `step` (a relaxation, applied) left the positions it changed.
void noteRelaxed(std::unordered_map<std::size_t, core::Vec4f>& relaxed, const core::EditStep& step,
                 const core::GeometryImage& positions) {
  const std::vector<std::uint8_t> moved = changedSamples(step, positions.side(), positions.rows());
  for (std::size_t k = 0; k < moved.size(); ++k)
    if (moved[k]) relaxed[k] = positions.texels()[k];
}

} // namespace

bool KeepDetailRun::relaxesAfter(int dabs) {
  if (dabs < std::max(kFirstRelaxationDab, 2 * relaxedAt)) return false;
  relaxedAt = dabs;
  return true;
}

void KeepDetailRun::applied(const core::EditStep& step, const core::Document& mirror,
                            const std::string& label) {
  noteRelaxed(relaxed, step, mirror.positions);
  relaxations =
      relaxations.tiles.empty() ? step : core::combineSteps(relaxations, step, mirror, label);
}

core::EditStep relaxDabsSoFar(KeepDetailRun& run, const core::Document& mirror,
                              const core::EditStep& soFar, const std::string& label, float radius) {
  if (!addDabChanges(run.dabChanged, run.relaxed, soFar, mirror.positions)) return {};
  return core::relaxChangedStep(mirror, run.dabChanged,
                                core::keepDetailMargin(mirror.positions, radius), label,
                                pinOptions(run.pinnedPath, mirror.positions));
}

} // namespace octaclay::app
