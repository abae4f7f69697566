#include "rd_measure.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/measure/rd_plot.h"
#include "octaclay/core/measure/surface_distance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

namespace octaclay::app {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double angleDegrees(core::Vec3f a, core::Vec3f b) {
  // atan2 of sine and cosine stays accurate near 0, where acos of a rounded cosine does not.
  return std::atan2(static_cast<double>(core::length(core::cross(a, b))),
                    static_cast<double>(core::dot(a, b))) *
         180.0 / std::numbers::pi;
}

std::string number(double v, const char* format = "%.4g") {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[40];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

} // namespace

RdReference makeRdReference(const core::GeometryImage& image) {
  RdReference r;
  r.image = image;
  r.mesh = core::extractMesh(image);
  r.normals = core::computeNormals(image);
  r.meshNormals = areaWeightedNormals(r.mesh);
  return r;
}

// The cross product's length is twice the area, so summing unnormalized face normals weights
// them by area, as core::vertexNormal does on the image.
std::vector<core::Vec3f> areaWeightedNormals(const core::TriangleMesh& mesh) {
  std::vector<core::Vec3f> normals(mesh.positions.size());
  for (const auto& t : mesh.triangles) {
    const core::Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const core::Vec3f n = core::cross(b - a, c - a);
    for (std::uint32_t v : t)
      normals[v] += n;
  }
  for (core::Vec3f& n : normals)
    n = core::normalize(n);
  return normals;
}

Distortion measureDistortion(const RdReference& reference, const core::GeometryImage& decoded,
                             std::size_t samples) {
  Distortion d;
  const core::SurfaceDistance distance = core::compareSurfaces(
      reference.mesh, core::extractMesh(decoded), {.samplesPerSurface = samples});
  d.psnr = distance.psnr;
  d.rms = distance.rms;
  d.hausdorff = distance.hausdorff;
  d.boundedQueries = distance.boundedQueries;
  d.samples = distance.samples;
  d.stride = distance.stride;
  d.maxSeamGap = core::maxSeamGap(decoded);
  const std::vector<core::Vec3f> normals = core::computeNormals(decoded);
  const int n = decoded.size();
  double sum = 0;
  std::size_t count = 0;
  core::forEachCanonicalRun(n, [&](int j, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * (n + 1) + i;
      sum += angleDegrees(reference.normals[k], normals[k]);
      ++count;
    }
  });
  d.normalAngleDeg = count ? sum / static_cast<double>(count) : 0;
  return d;
}

double bitsPerVertex(std::size_t bytes, int n) {
  return 8.0 * static_cast<double>(bytes) / (static_cast<double>(n) * n + 2);
}

std::vector<core::CodecParams> sweepSettings(const core::Codec& codec) {
  const std::string_view id = codec.info.id;
  std::vector<core::CodecParams> out;
  auto qualities = [&](std::initializer_list<double> list) {
    for (double q : list)
      out.push_back({.quality = q, .mode = {}});
  };
  if (id == "exr") {
    for (const char* mode : {"half", "pxr24", "piz", "zip"})
      out.push_back({.quality = 0, .mode = mode});
  } else if (id == "bytepack") {
    qualities({1, 4, 16, 64, 256}); // regions per side R
  } else if (id == "dct") {
    qualities({10, 30, 50, 70, 85, 95, 100});
  } else if (id == "wavelet") {
    qualities({3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6});
  } else if (codec.info.lossy) {
    qualities({codec.info.defaultQuality});
  } else {
    out.push_back({.quality = 0, .mode = {}});
  }
  return out;
}

std::string describeSetting(const core::Codec& codec, const core::CodecParams& params) {
  if (!params.mode.empty()) return params.mode;
  if (!codec.info.lossy) return "-";
  if (codec.info.id == "bytepack") return "R=" + number(params.quality);
  return "q=" + number(params.quality);
}

core::FloatImage positionsImage(const core::GeometryImage& image) {
  core::FloatImage out{image.size(), 3, {}};
  out.texels.reserve(image.texelCount() * 3);
  for (const core::Vec4f& t : image.texels())
    out.texels.insert(out.texels.end(), {t.x, t.y, t.z});
  return out;
}

core::GeometryImage toGeometryImage(const core::FloatImage& xyz, const core::GeometryImage& like) {
  if (xyz.n != like.size() || xyz.channels != 3 || xyz.texels.size() != like.texelCount() * 3)
    throw core::Error(core::ErrorKind::InvalidInput,
                      "decoded positions do not match the image they were made from");
  core::GeometryImage out = like;
  std::span<core::Vec4f> texels = out.texels();
  for (std::size_t k = 0; k < texels.size(); ++k) {
    texels[k].x = xyz.texels[3 * k];
    texels[k].y = xyz.texels[3 * k + 1];
    texels[k].z = xyz.texels[3 * k + 2];
  }
  return out;
}

RdPoint measureCodec(const RdReference& reference, const core::Codec& codec,
                     const core::CodecParams& params, std::size_t samples, int repeats) {
  const core::FloatImage input = positionsImage(reference.image);
  RdPoint p;
  p.codec = std::string(codec.info.id);
  p.setting = describeSetting(codec, params);
  p.quality = params.quality;
  p.encodeMs = p.decodeMs = std::numeric_limits<double>::infinity();
  std::vector<std::uint8_t> bytes;
  core::FloatImage output;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    auto start = Clock::now();
    bytes = codec.encode(input, params);
    p.encodeMs = std::min(p.encodeMs, millisecondsSince(start));
    start = Clock::now();
    output = codec.decode(bytes, input.n, input.channels);
    p.decodeMs = std::min(p.decodeMs, millisecondsSince(start));
  }
  p.bytes = bytes.size();
  p.bitsPerVertex = bitsPerVertex(p.bytes, input.n);
  p.exact = output.texels == input.texels;
  p.distortion = measureDistortion(reference, toGeometryImage(output, reference.image), samples);
  return p;
}

std::vector<RdPoint> sweep(const RdReference& reference, std::size_t samples) {
  std::vector<RdPoint> points;
  for (const core::Codec& codec : core::codecs())
    for (const core::CodecParams& params : sweepSettings(codec)) {
      try {
        points.push_back(measureCodec(reference, codec, params, samples));
      } catch (const core::Error& e) {
        // A setting a codec does not offer is left out of the curve, with a note.
        std::cerr << "sweep: " << codec.info.id << " " << describeSetting(codec, params)
                  << " skipped: " << e.what() << "\n";
      }
    }
  for (int bits = 8; bits <= 16; ++bits)
    points.push_back(measureDraco(reference, bits, 7, samples));
  return points;
}

std::string rdMarkdown(std::span<const RdPoint> points, const std::string& title) {
  std::ostringstream out;
  out << "# " << title << "\n\n"
      << "| codec | setting | bytes | bits/vertex | PSNR (dB) | RMS | Hausdorff | normal "
         "angle (deg) | max seam gap | encode ms | decode ms |\n"
      << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const RdPoint& p : points)
    out << "| " << p.codec << " | " << p.setting << " | " << p.bytes << " | "
        << number(p.bitsPerVertex, "%.3f") << " | "
        << (p.exact ? "exact" : number(p.distortion.psnr, "%.2f")) << " | "
        << number(p.distortion.rms, "%.3g") << " | " << number(p.distortion.hausdorff, "%.3g")
        << " | " << number(p.distortion.normalAngleDeg, "%.4f") << " | "
        << number(p.distortion.maxSeamGap, "%.3g") << " | " << number(p.encodeMs, "%.1f") << " | "
        << number(p.decodeMs, "%.1f") << " |\n";
  return out.str();
}

std::string rdCsv(std::span<const RdPoint> points) {
  std::ostringstream out;
  out << "codec,setting,quality,bytes,bits_per_vertex,psnr_db,rms,hausdorff,normal_angle_deg,"
         "max_seam_gap,encode_ms,decode_ms,exact\n";
  for (const RdPoint& p : points)
    out << p.codec << "," << p.setting << "," << number(p.quality, "%.6g") << "," << p.bytes << ","
        << number(p.bitsPerVertex, "%.6g") << "," << number(p.distortion.psnr, "%.6g") << ","
        << number(p.distortion.rms, "%.6g") << "," << number(p.distortion.hausdorff, "%.6g") << ","
        << number(p.distortion.normalAngleDeg, "%.6g") << ","
        << number(p.distortion.maxSeamGap, "%.6g") << "," << number(p.encodeMs, "%.3f") << ","
        << number(p.decodeMs, "%.3f") << "," << (p.exact ? 1 : 0) << "\n";
  return out.str();
}

std::vector<std::filesystem::path> stageRdReport(std::span<const RdPoint> points,
                                                 const std::string& title,
                                                 const std::filesystem::path& directory,
                                                 core::OutputSet& set) {
  const std::vector<std::filesystem::path> paths{directory / "rd.md", directory / "rd.csv",
                                                 directory / "rd.png"};
  set.stageText(paths[0], rdMarkdown(points, title));
  set.stageText(paths[1], rdCsv(points));
  // One curve per codec (and exr mode), in the order met; Draco first, the reference.
  std::vector<core::RdSeries> series{{"draco (level 7)", {}}};
  std::map<std::string, std::size_t> seriesOf;
  for (const RdPoint& p : points) {
    const std::string label = p.codec == "draco" ? "draco (level 7)"
                              : p.codec == "exr" ? "exr " + p.setting
                                                 : p.codec;
    auto [it, added] = seriesOf.try_emplace(label, series.size());
    if (label == "draco (level 7)")
      it->second = 0;
    else if (added)
      series.push_back({label, {}});
    series[it->second].points.push_back(
        {p.bitsPerVertex, p.exact ? std::numeric_limits<double>::infinity() : p.distortion.psnr,
         p.exact ? 0.0 : p.distortion.normalAngleDeg});
  }
  core::stageRdPlot(series, title, paths[2], set);
  return paths;
}

std::vector<std::filesystem::path> writeRdReport(std::span<const RdPoint> points,
                                                 const std::string& title,
                                                 const std::filesystem::path& directory) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory))
    throw core::Error(core::ErrorKind::Io,
                      directory.string() + ": cannot create the report folder");
  core::OutputSet set;
  std::vector<std::filesystem::path> paths = stageRdReport(points, title, directory, set);
  set.commit();
  return paths;
}

} // namespace octaclay::app
