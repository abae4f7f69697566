#pragma once

// Rate–distortion measurements of the position codecs (issue 8) and of Draco on the same
// mesh: the figures `octaclay-cli compress --json`, `compress --sweep` and bench_codecs print.

#include "octaclay/core/codec/codec.h"
#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace octaclay::app {

/// The original surface, measured once and compared with every decoded version of it.
struct RdReference {
  core::GeometryImage image;
  core::TriangleMesh mesh;              ///< extractMesh at full resolution
  std::vector<core::Vec3f> normals;     ///< core::computeNormals, (N+1)² samples
  std::vector<core::Vec3f> meshNormals; ///< area-weighted, per mesh vertex (Draco's matches)
};
RdReference makeRdReference(const core::GeometryImage& image);
/// Per-vertex unit normals: the incident triangles' normals weighted by area.
std::vector<core::Vec3f> areaWeightedNormals(const core::TriangleMesh& mesh);

/// How far a decoded surface is from the reference.
struct Distortion {
  double psnr = 0;                ///< dB, 20 log10(1/rms); +inf when equal
  double rms = 0;                 ///< fraction of the bounding-box diagonal
  double hausdorff = 0;           ///< fraction of the bounding-box diagonal
  double normalAngleDeg = 0;      ///< mean angle between corresponding vertex normals
  double maxSeamGap = 0;          ///< object units; 0 = no cracks
  std::size_t boundedQueries = 0; ///< closest-point queries stopped at their work bound
  std::size_t samples = 0;        ///< points measured
  std::size_t stride = 1;         ///< every stride-th sample measured
};
/// samples: random points per surface besides the vertices (compareSurfaces).
Distortion measureDistortion(const RdReference& reference, const core::GeometryImage& decoded,
                             std::size_t samples);

/// One point of a rate–distortion curve.
struct RdPoint {
  std::string codec;   ///< codec id, or "draco"
  std::string setting; ///< e.g. "q=0.001", "zip", "qp=14"
  double quality = 0;  ///< the number the setting varies (draco: quantization bits)
  std::size_t bytes = 0;
  double bitsPerVertex = 0; ///< 8·bytes / (N² + 2)
  double encodeMs = 0, decodeMs = 0;
  bool exact = false; ///< decoded bit for bit equal to the input
  Distortion distortion;
};

double bitsPerVertex(std::size_t bytes, int n);

/// The settings a sweep tries for a codec, from coarse to fine: several qualities for lossy
/// codecs, each mode for `exr`, one for the others.
std::vector<core::CodecParams> sweepSettings(const core::Codec& codec);
std::string describeSetting(const core::Codec& codec, const core::CodecParams& params);

/// The positions' xyz as a 3-channel image (what Draco codes too), and back (w from `like`).
core::FloatImage positionsImage(const core::GeometryImage& image);
core::GeometryImage toGeometryImage(const core::FloatImage& xyz, const core::GeometryImage& like);

/// Encodes the reference's xyz with codec, decodes it and measures (times: best of `repeats`).
RdPoint measureCodec(const RdReference& reference, const core::Codec& codec,
                     const core::CodecParams& params, std::size_t samples, int repeats = 1);
/// Draco on the reference's mesh: positions quantized to `bits`, compression level 0 … 10.
RdPoint measureDraco(const RdReference& reference, int bits, int compressionLevel,
                     std::size_t samples, int repeats = 1);

/// Every codec at each sweep setting, then Draco at 8 … 16 bits (level 7).
std::vector<RdPoint> sweep(const RdReference& reference, std::size_t samples);

std::string rdMarkdown(std::span<const RdPoint> points, const std::string& title);
std::string rdCsv(std::span<const RdPoint> points);
/// Stages rd.md, rd.csv and rd.png in directory (which must exist) into `set`; returns the
/// three paths.
std::vector<std::filesystem::path> stageRdReport(std::span<const RdPoint> points,
                                                 const std::string& title,
                                                 const std::filesystem::path& directory,
                                                 core::OutputSet& set);
/// stageRdReport into directory (created), committed at once; returns the three paths.
std::vector<std::filesystem::path> writeRdReport(std::span<const RdPoint> points,
                                                 const std::string& title,
                                                 const std::filesystem::path& directory);

} // namespace octaclay::app
