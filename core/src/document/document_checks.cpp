#include "octaclay/core/document/document_checks.h"

#include "detail/finite_rows.h"
#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace octaclay::core {
namespace {

// A row's samples with a coordinate that is not finite, and the largest magnitude of its
// coordinates when there is none: vector code (four samples' four lanes a step, an AVX2 copy
// chosen at run time). A maximum of magnitudes is exact in any order.
struct RowCheck {
  int notFinite = 0;
  float largest = 0;
};

__attribute__((target_clones("avx2", "default"))) RowCheck checkRow(const Vec4f* row, int count) {
  const float* v = &row[0].x;
  RowCheck check;
  check.notFinite = detail::nonFiniteSamples(row, count);
  if (check.notFinite > 0) return check;
  float lanes[4][4] = {};
  int i = 0;
  for (; i + 4 <= count; i += 4)
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 4; ++c) {
        const float m = std::fabs(v[4 * (i + k) + c]);
        lanes[k][c] = lanes[k][c] < m ? m : lanes[k][c];
      }
  for (; i < count; ++i)
    for (int c = 0; c < 4; ++c) {
      const float m = std::fabs(v[4 * i + c]);
      lanes[0][c] = lanes[0][c] < m ? m : lanes[0][c];
    }
  for (int k = 0; k < 4; ++k) // w is the saliency, not a coordinate
    check.largest = std::max({check.largest, lanes[k][0], lanes[k][1], lanes[k][2]});
  return check;
}

} // namespace

std::optional<std::string> positionsProblem(const GeometryImage& positions) {
  // Bands of rows on every core, each its first non-finite sample and its largest magnitude; the
  // first band with a non-finite sample names the same sample a row-by-row scan would.
  const int side = positions.side(), rows = positions.rows();
  struct Band {
    int badI = -1, badJ = -1;
    float largest = 0;
  };
  std::vector<Band> bands(static_cast<std::size_t>(rows));
  detail::parallelRows(rows, [&](int rowBegin, int rowEnd) {
    Band& band = bands[static_cast<std::size_t>(rowBegin)];
    float largest = 0;
    for (int j = rowBegin; j < rowEnd; ++j) {
      const Vec4f* row = &positions.at(0, j);
      const RowCheck check = checkRow(row, side);
      if (check.notFinite == 0) {
        largest = std::max(largest, check.largest);
        continue;
      }
      for (int i = 0; i < side; ++i) { // the row's first
        const Vec4f& t = row[i];
        if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z)) {
          band.badI = i;
          band.badJ = j;
          return;
        }
      }
    }
    band.largest = largest;
  });
  float largest = 0;
  for (const Band& band : bands) {
    if (band.badJ >= 0)
      return "position at sample (" + std::to_string(band.badI) + ", " + std::to_string(band.badJ) +
             ") is not a finite number";
    largest = std::max(largest, band.largest);
  }
  if (largest > kMaxCoordinate) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", static_cast<double>(largest));
    return std::string("a coordinate of magnitude ") + text +
           " is too large: coordinates beyond 1e15 are refused (scale the model down)";
  }
  return std::nullopt;
}

std::optional<std::string> sizeProblem(const GeometryImage& positions) {
  return sizeProblem(boundingBox(positions));
}

std::optional<std::string> sizeProblem(const BoundingBox& box) {
  if (box.empty()) return "the model has no samples";
  const Vec3f low = box.min, high = box.max;
  const double dx = double(high.x) - low.x, dy = double(high.y) - low.y,
               dz = double(high.z) - low.z;
  const double diagonal = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double largest =
      std::max({std::abs(double(low.x)), std::abs(double(low.y)), std::abs(double(low.z)),
                std::abs(double(high.x)), std::abs(double(high.y)), std::abs(double(high.z))});
  if (!(diagonal > 0))
    return "the model has no size: every sample lies at one point (a collapsed model); there is "
           "nothing to measure or shape";
  char text[64];
  if (diagonal < kMinDiagonal) {
    std::snprintf(text, sizeof text, "%.3g", diagonal);
    return std::string("the model is ") + text +
           " across, below the 1e-12 a model must measure (scale it up)";
  }
  if (diagonal < 1e-6 * largest) {
    std::snprintf(text, sizeof text, "%.3g across at coordinates of %.3g", diagonal, largest);
    return std::string("the model is collapsed: ") + text +
           ", below float precision there (move it towards the origin or scale it up)";
  }
  return std::nullopt;
}

std::optional<std::string> layerValuesProblem(const Layer& layer, int size) {
  const std::size_t channels = static_cast<std::size_t>(layer.channels);
  for (std::size_t c = 0; c < channels; ++c)
    if (layer.uniform() && !std::isfinite(layer.fill[c]))
      return "layer " + layer.name + " holds a value that is not a finite number";
  for (std::size_t k = 0; k < layer.texels.size(); ++k)
    if (!std::isfinite(layer.texels[k])) {
      const std::size_t texel = k / channels, side = static_cast<std::size_t>(size) + 1;
      return "layer " + layer.name + " holds a value that is not a finite number at sample (" +
             std::to_string(texel % side) + ", " + std::to_string(texel / side) + ")";
    }
  return std::nullopt;
}

void requireUsableSize(const GeometryImage& positions, const std::string& what) {
  if (const auto problem = sizeProblem(positions))
    throw Error(ErrorKind::InvalidInput, what + ": " + *problem);
}

void requireOctahedral(const GeometryImage& positions, const std::string& operation,
                       const std::string& what) {
  if (positions.topology() == Topology::Octahedral) return;
  throw Error(ErrorKind::InvalidArgument, operation + " works on octahedral documents only; " +
                                              what + " is a " +
                                              std::string(topologyName(positions.topology())) +
                                              " (" + std::to_string(positions.width()) + "x" +
                                              std::to_string(positions.height()) + " cells)");
}

std::optional<std::string> layerChannelsProblem(const std::vector<std::string>& channels) {
  const Document defaults;
  for (const Layer* layer : {&defaults.diffuse, &defaults.feature, &defaults.mask}) {
    const auto names = layer->channelNames();
    int present = 0;
    for (const std::string& n : names)
      present += std::count(channels.begin(), channels.end(), layer->name + "." + n) > 0;
    if (present != 0 && present != layer->channels)
      return "layer " + layer->name + " has " + std::to_string(present) + " of its " +
             std::to_string(layer->channels) + " channels";
  }
  return std::nullopt;
}

} // namespace octaclay::core
