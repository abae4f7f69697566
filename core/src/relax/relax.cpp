#include "octaclay/core/relax/relax.h"

#include "relax/offset_field.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace octaclay::core {
namespace {

void checkOptions(const RelaxOptions& options) {
  if (options.iterations < 0 || options.iterations > kMaxRelaxIterations)
    throw Error(ErrorKind::InvalidArgument,
                "iterations " + std::to_string(options.iterations) + " is outside 0 to " +
                    std::to_string(kMaxRelaxIterations) + "; leave it at 0 to choose from N");
}

void checkFinitePositions(const GeometryImage& image) {
  for (int j = 0; j <= image.size(); ++j)
    for (int i = 0; i <= image.size(); ++i) {
      const Vec4f& p = image.at(i, j);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(ErrorKind::InvalidInput,
                    "sample (" + std::to_string(i) + ", " + std::to_string(j) +
                        ") has a non-finite position; the document is damaged and cannot be "
                        "relaxed");
    }
}

int fineIterations(const RelaxOptions& options) {
  return options.iterations > 0 ? options.iterations : 1;
}

} // namespace

Document evenOutSamples(const Document& document, const RelaxOptions& options,
                        const RelaxProgress& progress) {
  checkOptions(options);
  checkFinitePositions(document.positions);
  detail::OffsetField field(document.size());
  field.freeAll();
  if (!detail::solveOffsets(document.positions, field, fineIterations(options), progress))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  Document result = document; // samples that do not move keep their texels
  detail::resampleDocument(document, field, result);
  if (progress && !progress(1.0f))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return result;
}

std::vector<TexelRect> relaxRegions(Document& document, const std::vector<TexelRect>& regions,
                                    const RelaxOptions& options) {
  checkOptions(options);
  checkFinitePositions(document.positions);
  const int n = document.size();
  detail::OffsetField field(n);
  for (const TexelRect& r : regions)
    field.freeInside(r);
  detail::solveOffsets(document.positions, field, fineIterations(options), {});
  // The changed texels' bounding rectangle in each quarter of the image keeps seam partners on
  // opposite borders in separate rectangles.
  std::vector<TexelRect> changed;
  const int half = n / 2;
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx) {
      int x0 = n + 1, y0 = n + 1, x1 = -1, y1 = -1;
      for (int j = qy * (half + 1); j <= (qy ? n : half); ++j)
        for (int i = qx * (half + 1); i <= (qx ? n : half); ++i) {
          const auto& d = field.offset[field.index(i, j)];
          if (d[0] == 0.0f && d[1] == 0.0f) continue;
          x0 = std::min(x0, i), y0 = std::min(y0, j), x1 = std::max(x1, i), y1 = std::max(y1, j);
        }
      if (x1 >= 0) changed.push_back({x0, y0, x1 - x0 + 1, y1 - y0 + 1});
    }
  if (changed.empty()) return changed;
  const Document before = document; // resampling reads around each moved sample
  detail::resampleDocument(before, field, document);
  return changed;
}

} // namespace octaclay::core
