#pragma once

#include "octaclay/core/lod/saliency.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <map>
#include <vector>

namespace octaclay::gpu {

/// The saliency of a GpuDocument's positions computed on the GPU (thesis 4.3: "a pass of the
/// geometry image can add to the alpha channel the saliency of the mesh"), the same measure as
/// core::computeSaliency: per sample the normal (core::vertexNormal), curvature = the mean of
/// 1 − n·n' over its four neighbours, then Σ over scales s of |G(curvature, s) − G(curvature,
/// 2s)| with separable Gaussians (taps to ⌈2σ⌉, at least 1) over the grid's tiling (the ball's
/// octahedral one, a torus's periods, a plane's clamped boundary), seamed so identified samples
/// are equal, normalised to [0, 1] by its maximum. Written into the positions'
/// alpha of the texture and the mirror (xyz untouched). Create and use with the document's context
/// current.
class SaliencyPass {
public:
  /// Compiles the passes. Throws GlError.
  SaliencyPass();

  /// Recomputes the whole image's saliency into the positions' alpha. Throws GlError.
  void run(GpuDocument& document, const core::SaliencyOptions& options = {});

  /// The scales used for an image of N samples across (core::saliencySamplesAcross):
  /// options.scales, or max(1, s · N/256) for s = 1, 2, 4, 8, 16.
  static std::vector<float> scalesFor(float n, const core::SaliencyOptions& options);

private:
  /// A Gaussian of the curvature at sigma, made once per run (G(2s) is the next scale's G(s)).
  const Texture& blurred(float sigma, const core::SampleGrid& grid);
  Texture& temporary(int slot, int width, int height);
  /// Sets the grid's uniforms (u_size, u_cells, u_topology) of a program that uses the prelude.
  static void setGrid(const Program& program, const core::SampleGrid& grid);

  Program normalProgram_, curvatureProgram_, blurProgram_, combineProgram_, seamProgram_;
  RectPass rectPass_;
  Buffer kernel_; // the blur's weights (shader storage, binding 1)
  Texture normals_, curvature_, horizontal_;
  std::map<float, Texture> blurred_;
  std::vector<Texture> sums_;
};

} // namespace octaclay::gpu
