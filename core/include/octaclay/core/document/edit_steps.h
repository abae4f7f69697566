#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_step.h"

#include <string>
#include <vector>

namespace octaclay::core {

/// The undo step that turns `before` into `after` (same size): every tile of every layer
/// where a bit differs, among the tiles that meet `within` (all tiles when it is empty).
/// Uniform layers count as their fill. Throws Error(InvalidArgument) when the sizes differ.
EditStep recordDifference(const Document& before, const Document& after, std::string label,
                          const std::vector<TexelRect>& within = {});

/// One undo step doing `first` then `second`, from the document `current` that holds the state
/// after both (e.g. a stroke and the relaxation that followed it): undoing it restores the
/// state before `first` bit for bit.
EditStep combineSteps(const EditStep& first, const EditStep& second, const Document& current,
                      std::string label);

} // namespace octaclay::core
