#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_step.h"
#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace octaclay::app {

/// Keep detail's state over one stroke (SculptSession): the samples its dabs changed, where its
/// relaxations between dabs left the samples they moved, and what those relaxations changed.
struct KeepDetailRun {
  std::vector<std::array<float, 2>> pinnedPath; ///< image points held: the stroke's first, last
  int relaxedAt = 0; ///< the dab count at the last relaxation between dabs
  /// The samples the dabs changed so far ((W+1)×(H+1); empty: none known yet): what each relaxation
  /// grows its region from. What relaxations moved is not in it (the region would creep outward
  /// by a margin each time) unless a dab changed it again.
  std::vector<std::uint8_t> dabChanged;
  /// Where the relaxations left the samples they moved (index → position), to tell a dab's
  /// change from theirs.
  std::unordered_map<std::size_t, core::Vec4f> relaxed;
  core::EditStep relaxations; ///< what they changed, as one step

  /// Whether a dragging stroke relaxes after its dabs-th dab: at the 4th, then each time the
  /// count doubles (a limb pulled in one stroke takes its samples in steps that each stay within
  /// the tolerance; a stroke of d dabs relaxes about log2(d / 4) + 1 times). Notes it if so.
  bool relaxesAfter(int dabs);
  /// A relaxation between dabs was applied to mirror: noted, and folded into relaxations.
  void applied(const core::EditStep& step, const core::Document& mirror, const std::string& label);
};

/// The relaxation of what the stroke's dabs changed so far (soFar: its record), over mirror:
/// core::relaxChangedStep within core::keepDetailMargin of radius, the pinned path held. No tiles:
/// nothing to relax. No GL and nothing but run and mirror read: after a stroke a worker thread
/// runs it (StrokeEnding::relax) while nothing writes the mirror.
core::EditStep relaxDabsSoFar(KeepDetailRun& run, const core::Document& mirror,
                              const core::EditStep& soFar, const std::string& label, float radius);

} // namespace octaclay::app
