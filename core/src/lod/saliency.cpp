// CPU reference of the saliency pass (saliency.h, SaliencyOptions): curvature as the change of
// normal, then Lee et al. 2005 centre-surround differences of Gaussian-blurred curvature.
#include "octaclay/core/lod/saliency.h"

#include "detail/parallel_rows.h"
#include "detail/unit_scale.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/geometry/normals.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace octaclay::core {
namespace {

// Curvature of sample s: the mean over its four axis neighbours q of 1 − n(s)·n(q), the
// neighbours read through the grid's wrap() (the ball's octahedral tiling, a torus's periods, a
// plane's boundary).
std::vector<float> curvature(const GeometryImage& image, const std::vector<Vec3f>& normals) {
  const SampleGrid& grid = image.grid();
  const int side = image.side(), rows = image.rows();
  std::vector<float> out(image.texelCount());
  const auto normalAt = [&](Sample s) {
    const Sample w = wrap(grid, s);
    return normals[static_cast<std::size_t>(w.j) * side + w.i];
  };
  detail::parallelRows(rows, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i < side; ++i) {
        const Vec3f c = normals[static_cast<std::size_t>(j) * side + i];
        float sum = 0;
        for (const Sample d : {Sample{1, 0}, Sample{-1, 0}, Sample{0, 1}, Sample{0, -1}})
          sum += 1 - dot(c, normalAt({i + d.i, j + d.j}));
        out[static_cast<std::size_t>(j) * side + i] = sum * 0.25f;
      }
  });
  return out;
}

// The truncated (radius ⌈2σ⌉) normalised Gaussian kernel of σ.
std::vector<float> gaussianKernel(float sigma) {
  const int radius = std::max(1, static_cast<int>(std::ceil(2 * sigma)));
  std::vector<float> k(2 * radius + 1);
  float sum = 0;
  for (int d = -radius; d <= radius; ++d)
    sum += k[d + radius] = std::exp(-0.5f * float(d * d) / (sigma * sigma));
  for (float& w : k)
    w /= sum;
  return k;
}

// Gaussian blur of a field over the grid's tiling of the plane. The octahedral tiling's
// symmetries are half-turns and translations, a torus's translations, and a plane's boundary
// clamps each axis alone: each maps rows to rows, so the 2-D blur of the tiled field is exactly
// a row pass followed by a column pass, each reading through wrap().
std::vector<float> blur(const SampleGrid& grid, const std::vector<float>& field, float sigma) {
  const std::vector<float> kernel = gaussianKernel(sigma);
  const int radius = static_cast<int>(kernel.size() / 2);
  const int w = grid.width, h = grid.height, side = w + 1;
  const auto at = [&](const std::vector<float>& f, int i, int j) {
    const Sample s = wrap(grid, {i, j});
    return f[static_cast<std::size_t>(s.j) * side + s.i];
  };
  std::vector<float> rows(field.size()), out(field.size());
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<float>& from = pass == 0 ? field : rows;
    std::vector<float>& to = pass == 0 ? rows : out;
    detail::parallelRows(h + 1, [&](int rowBegin, int rowEnd) {
      for (int j = rowBegin; j < rowEnd; ++j)
        for (int i = 0; i < side; ++i) {
          float sum = 0;
          const bool inside =
              pass == 0 ? i - radius >= 0 && i + radius <= w : j - radius >= 0 && j + radius <= h;
          if (inside) {
            const float* base = pass == 0 ? &from[static_cast<std::size_t>(j) * side + i - radius]
                                          : &from[static_cast<std::size_t>(j - radius) * side + i];
            const std::size_t stride = pass == 0 ? 1 : side;
            for (int d = 0; d <= 2 * radius; ++d)
              sum += kernel[d] * base[d * stride];
          } else {
            for (int d = -radius; d <= radius; ++d)
              sum += kernel[d + radius] * (pass == 0 ? at(from, i + d, j) : at(from, i, j + d));
          }
          to[static_cast<std::size_t>(j) * side + i] = sum;
        }
    });
  }
  return out;
}

} // namespace

void computeSaliency(GeometryImage& image, const SaliencyOptions& options) {
  if (const int e = detail::unitScaleExponent(image); e != 0) { // in the model's own units
    GeometryImage scaled = detail::scaledPositions(image, e);
    computeSaliency(scaled, options);
    for (std::size_t k = 0; k < image.texels().size(); ++k)
      image.texels()[k].w = scaled.texels()[k].w;
    return;
  }
  const SampleGrid& grid = image.grid();
  std::vector<float> scales = options.scales;
  if (scales.empty())
    for (const float s : {1.0f, 2.0f, 4.0f, 8.0f, 16.0f})
      scales.push_back(std::max(1.0f, s * saliencySamplesAcross(grid) / 256.0f));
  const std::vector<float> curv = curvature(image, computeNormals(image));

  std::map<float, std::vector<float>> blurred; // σ → G(curvature, σ), each σ blurred once
  const auto blurredAt = [&](float sigma) -> const std::vector<float>& {
    auto it = blurred.find(sigma);
    if (it == blurred.end()) it = blurred.emplace(sigma, blur(grid, curv, sigma)).first;
    return it->second;
  };
  std::vector<float> saliency(curv.size(), 0.0f);
  for (const float s : scales) {
    const std::vector<float>& centre = blurredAt(s);
    const std::vector<float>& surround = blurredAt(2 * s);
    for (std::size_t k = 0; k < saliency.size(); ++k)
      saliency[k] += std::abs(centre[k] - surround[k]);
  }
  const float peak = *std::max_element(saliency.begin(), saliency.end());
  const float scale = peak > 0 ? 1.0f / peak : 0.0f;
  std::span<Vec4f> texels = image.texels();
  for (std::size_t k = 0; k < texels.size(); ++k)
    texels[k].w = saliency[k] * scale;
  // Identified samples have equal curvature and blurs up to rounding: give them one value, the
  // canonical sample's (a torus's: the one in columns and rows below W and H).
  if (grid.topology == Topology::Plane) return; // no sample is another's
  const bool ball = grid.topology == Topology::Octahedral;
  std::array<Sample, 4> same;
  const auto unify = [&](Sample s) {
    const int count = identifiedSamples(grid, s, same);
    const float w = image.at(ball ? canonical(grid.width, s) : wrap(grid, s)).w;
    for (int c = 0; c < count; ++c)
      image.at(same[c]).w = w;
  };
  for (int i = 0; i <= grid.width; ++i)
    for (const int j : {0, grid.height})
      unify({i, j});
  for (int j = 0; j <= grid.height; ++j)
    for (const int i : {0, grid.width})
      unify({i, j});
}

float saliencySamplesAcross(const SampleGrid& grid) {
  return static_cast<float>(std::sqrt(double(grid.width) * double(grid.height)));
}

} // namespace octaclay::core
