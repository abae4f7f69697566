// Draco, the reference curve of the rate–distortion report: the reference's full-resolution
// mesh with its positions quantized to 8 … 16 bits, encoded, decoded and measured like ours.

#include "rd_measure.h"

#include "octaclay/core/error.h"
#include "octaclay/core/measure/surface_distance.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <unordered_map>

namespace octaclay::app {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::unique_ptr<draco::Mesh> toDraco(const core::TriangleMesh& mesh) {
  auto owned = std::make_unique<draco::Mesh>();
  draco::Mesh& out = *owned;
  out.set_num_points(static_cast<draco::PointIndex::ValueType>(mesh.positions.size()));
  draco::GeometryAttribute position;
  position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false,
                sizeof(float) * 3, 0);
  const int id =
      out.AddAttribute(position, true, static_cast<std::uint32_t>(mesh.positions.size()));
  draco::PointAttribute* attribute = out.attribute(id);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const float xyz[3] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
    attribute->SetAttributeValue(draco::AttributeValueIndex(static_cast<std::uint32_t>(v)), xyz);
  }
  out.SetNumFaces(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    out.SetFace(draco::FaceIndex(static_cast<std::uint32_t>(t)),
                {draco::PointIndex(mesh.triangles[t][0]), draco::PointIndex(mesh.triangles[t][1]),
                 draco::PointIndex(mesh.triangles[t][2])});
  return owned;
}

core::TriangleMesh fromDraco(const draco::Mesh& mesh) {
  const draco::PointAttribute* position =
      mesh.GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (position == nullptr)
    throw core::Error(core::ErrorKind::InvalidInput, "Draco returned a mesh without positions");
  core::TriangleMesh out;
  out.positions.resize(mesh.num_points());
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    float xyz[3];
    position->GetMappedValue(p, xyz);
    out.positions[p.value()] = {xyz[0], xyz[1], xyz[2]};
  }
  out.triangles.resize(mesh.num_faces());
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    const draco::Mesh::Face& face = mesh.face(f);
    out.triangles[f.value()] = {face[0].value(), face[1].value(), face[2].value()};
  }
  return out;
}

// Nearest reference vertex of each point (Draco renumbers vertices): a uniform grid of cells
// searched in growing shells.
class NearestVertex {
public:
  explicit NearestVertex(const std::vector<core::Vec3f>& points) : points_(points) {
    for (core::Vec3f p : points)
      box_.extend(p);
    cell_ = std::max(box_.diagonal(), 1e-20f) / 512.0f;
    for (std::uint32_t k = 0; k < points.size(); ++k)
      cells_[key(cellOf(points[k]))].push_back(k);
  }

  std::uint32_t operator()(core::Vec3f q) const {
    const std::array<int, 3> c = cellOf(q);
    std::uint32_t best = 0;
    float bestDistance = std::numeric_limits<float>::infinity();
    for (int r = 0; r < 4096; ++r) {
      for (int dz = -r; dz <= r; ++dz)
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
            auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
            if (it == cells_.end()) continue;
            for (std::uint32_t k : it->second) {
              const core::Vec3f d = points_[k] - q;
              const float distance = core::dot(d, d);
              if (distance < bestDistance) {
                bestDistance = distance;
                best = k;
              }
            }
          }
      // Everything within r cells has been seen: nothing closer can be farther out.
      if (std::sqrt(bestDistance) <= static_cast<float>(r) * cell_) break;
    }
    return best;
  }

private:
  std::array<int, 3> cellOf(core::Vec3f p) const {
    return {static_cast<int>(std::floor((p.x - box_.min.x) / cell_)),
            static_cast<int>(std::floor((p.y - box_.min.y) / cell_)),
            static_cast<int>(std::floor((p.z - box_.min.z) / cell_))};
  }
  static std::int64_t key(std::array<int, 3> c) {
    return (static_cast<std::int64_t>(c[0] + 2048) << 42) |
           (static_cast<std::int64_t>(c[1] + 2048) << 21) | static_cast<std::int64_t>(c[2] + 2048);
  }

  const std::vector<core::Vec3f>& points_;
  core::BoundingBox box_;
  float cell_ = 1;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace

RdPoint measureDraco(const RdReference& reference, int bits, int compressionLevel,
                     std::size_t samples, int repeats) {
  const std::unique_ptr<draco::Mesh> input = toDraco(reference.mesh);
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
  const int speed = 10 - std::clamp(compressionLevel, 0, 10); // draco_encoder's -cl
  encoder.SetSpeedOptions(speed, speed);
  RdPoint p;
  p.codec = "draco";
  p.setting = "qp=" + std::to_string(bits);
  p.quality = bits;
  p.encodeMs = p.decodeMs = std::numeric_limits<double>::infinity();
  draco::EncoderBuffer buffer;
  std::unique_ptr<draco::Mesh> decoded;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    buffer.Clear();
    auto start = Clock::now();
    const draco::Status encoded = encoder.EncodeMeshToBuffer(*input, &buffer);
    p.encodeMs = std::min(p.encodeMs, millisecondsSince(start));
    if (!encoded.ok())
      throw core::Error(core::ErrorKind::InvalidArgument,
                        "Draco could not encode: " + encoded.error_msg_string());
    start = Clock::now();
    draco::DecoderBuffer in;
    in.Init(buffer.data(), buffer.size());
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&in);
    p.decodeMs = std::min(p.decodeMs, millisecondsSince(start));
    if (!result.ok())
      throw core::Error(core::ErrorKind::InvalidInput, "Draco could not decode its own stream: " +
                                                           result.status().error_msg_string());
    decoded = std::move(result).value();
  }
  p.bytes = buffer.size();
  p.bitsPerVertex = bitsPerVertex(p.bytes, reference.image.size());
  const core::TriangleMesh mesh = fromDraco(*decoded);
  const core::SurfaceDistance distance =
      core::compareSurfaces(reference.mesh, mesh, {.samplesPerSurface = samples});
  p.distortion.psnr = distance.psnr;
  p.distortion.rms = distance.rms;
  p.distortion.hausdorff = distance.hausdorff;
  p.distortion.maxSeamGap = 0; // one welded mesh: Draco cannot open a seam
  const std::vector<core::Vec3f> normals = areaWeightedNormals(mesh);
  const NearestVertex nearest(reference.mesh.positions);
  double sum = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const core::Vec3f a = reference.meshNormals[nearest(mesh.positions[v])], b = normals[v];
    sum += std::atan2(static_cast<double>(core::length(core::cross(a, b))),
                      static_cast<double>(core::dot(a, b)));
  }
  p.distortion.normalAngleDeg =
      mesh.positions.empty()
          ? 0
          : sum / static_cast<double>(mesh.positions.size()) * 180.0 / std::numbers::pi;
  return p;
}

} // namespace octaclay::app
