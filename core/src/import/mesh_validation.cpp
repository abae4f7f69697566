// Validation of imported meshes before spherical parameterization: cleanup, the topology checks
// (mesh_topology.cpp), hole filling (mesh_repair.cpp) and the genus.
// Based on: the Euler–Poincaré formula V − E + F = 2 − 2g for one closed orientable component.

#include "octaclay/core/import/mesh_validation.h"

#include "import/mesh_parts.h"
#include "import/mesh_readers.h"
#include "import/mesh_repair.h"
#include "import/mesh_topology.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

using detail::Analysis;
using detail::analyze;
using detail::fillHoles;
using detail::followCorners;
using detail::kNone;
using detail::Tri;

std::string counted(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string handles(long long genus) {
  if (genus == 1) return "one handle";
  return std::to_string(genus) + " handles";
}

// Vertex colours and corner texture coordinates as read (either may be empty).
struct Attributes {
  std::vector<Vec4f> vertexColours;
  std::vector<CornerUv> cornerUv;
};

ValidatedMesh validate(TriangleMesh mesh, Attributes attributes, const ValidationOptions& options,
                       const std::string& prefix, bool weld, std::size_t shortFaces) {
  auto refuse = [&](const std::string& what) {
    throw Error(ErrorKind::InvalidInput, prefix + what);
  };
  MeshCleanup cleanup;
  cleanup.degenerateFacesRemoved = shortFaces;
  auto& positions = mesh.positions;
  auto& tris = mesh.triangles;
  const std::size_t inputVertices = positions.size();

  if (tris.empty())
    refuse("no faces: there is no surface to import (only points or lines?) — export the "
           "model as a triangle or polygon mesh");
  if (inputVertices >= kNone) refuse("more than 4 billion vertices");
  std::vector<Vec4f>& colours = attributes.vertexColours;
  if (!colours.empty() && colours.size() != inputVertices)
    refuse(std::to_string(colours.size()) + " vertex colours for " + std::to_string(inputVertices) +
           " vertices");
  if (!attributes.cornerUv.empty() && attributes.cornerUv.size() != tris.size())
    refuse(std::to_string(attributes.cornerUv.size()) + " texture coordinate triples for " +
           std::to_string(tris.size()) + " triangles");
  std::vector<char> used(inputVertices, 0);
  for (std::size_t f = 0; f < tris.size(); ++f)
    for (const std::uint32_t v : tris[f]) {
      if (v >= inputVertices)
        refuse("triangle " + std::to_string(f + 1) + " refers to vertex " +
               std::to_string(std::uint64_t(v) + 1) + ", but there are only " +
               std::to_string(inputVertices) + " vertices — the file is damaged; re-export it");
      used[v] = 1;
    }
  for (std::size_t v = 0; v < inputVertices; ++v) {
    const Vec3f p = positions[v];
    if (used[v] && !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
      refuse("vertex " + std::to_string(v + 1) +
             " has a coordinate that is not a finite number (NaN or infinity) — the file is "
             "damaged; re-export it");
    if (used[v] && std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
      refuse("vertex " + std::to_string(v + 1) +
             " has a coordinate too large for a document (coordinates beyond 1e15 are "
             "refused) — scale the model down before importing it");
  }

  if (weld) {
    // Sort used vertices by position; every vertex maps to the lowest index at its position,
    // so vertex numbers in later messages are still the file's.
    std::vector<std::uint32_t> order;
    for (std::uint32_t v = 0; v < inputVertices; ++v)
      if (used[v]) order.push_back(v);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
      const Vec3f p = positions[a], q = positions[b];
      if (p.x != q.x) return p.x < q.x;
      if (p.y != q.y) return p.y < q.y;
      if (p.z != q.z) return p.z < q.z;
      return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> remap(inputVertices);
    std::iota(remap.begin(), remap.end(), std::uint32_t(0));
    for (std::size_t i = 1; i < order.size(); ++i)
      if (positions[order[i]] == positions[order[i - 1]]) {
        remap[order[i]] = remap[order[i - 1]];
        ++cleanup.duplicateVerticesWelded;
      }
    for (Tri& t : tris)
      for (std::uint32_t& v : t)
        v = remap[v];
  }

  // Which input triangle each triangle is, so that texture coordinates can follow them.
  const std::vector<Tri> inputTris = attributes.cornerUv.empty() ? std::vector<Tri>() : tris;
  std::vector<std::uint32_t> source(tris.size());
  std::iota(source.begin(), source.end(), std::uint32_t(0));
  auto keepFaces = [&](auto&& keep) {
    std::size_t out = 0;
    for (std::size_t f = 0; f < tris.size(); ++f)
      if (keep(f)) {
        tris[out] = tris[f];
        source[out++] = source[f];
      }
    const std::size_t removed = tris.size() - out;
    tris.resize(out);
    source.resize(out);
    return removed;
  };

  // Faces with a repeated corner bound no area and add an edge twice in opposite directions:
  // dropping them changes no other face's neighbourhood.
  cleanup.degenerateFacesRemoved += keepFaces([&](std::size_t f) {
    const Tri& t = tris[f];
    return !(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
  });

  // A face listed twice (in either winding) makes its edges look non-manifold; keep the first.
  {
    std::vector<std::pair<Tri, std::uint32_t>> keys(tris.size());
    for (std::size_t f = 0; f < tris.size(); ++f) {
      Tri key = tris[f];
      std::sort(key.begin(), key.end());
      keys[f] = {key, static_cast<std::uint32_t>(f)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<char> duplicate(tris.size(), 0);
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) {
        duplicate[keys[i].second] = 1;
        ++cleanup.duplicateFacesRemoved;
      }
    if (cleanup.duplicateFacesRemoved) keepFaces([&](std::size_t f) { return !duplicate[f]; });
  }
  if (tris.empty())
    refuse("no faces left after removing " +
           counted(cleanup.degenerateFacesRemoved, "degenerate face", "degenerate faces") +
           " — the file has no surface to import");

  Analysis a = analyze(mesh);
  if (a.nonManifoldEdges)
    refuse(counted(a.nonManifoldEdges, "edge", "edges") +
           " shared by more than two faces (non-manifold; e.g. the edge between vertices " +
           std::to_string(a.exampleA + 1) + " and " + std::to_string(a.exampleB + 1) + " has " +
           std::to_string(a.exampleFaces) +
           " faces) — remove the internal walls or fins, or split the parts, in a modelling "
           "tool");
  if (!a.orientable)
    refuse("not orientable: the faces cannot all be turned to one side (a Möbius strip or "
           "Klein bottle) — it has no outside, so it cannot become a geometry image");
  for (std::size_t f = 0; f < tris.size(); ++f)
    if (a.flip[f]) {
      std::swap(tris[f][1], tris[f][2]);
      ++cleanup.facesFlipped;
    }

  if (!a.holeEdges.empty() && options.fillHoles && options.maxHoleEdges >= 3) {
    cleanup.holesFilled =
        fillHoles(mesh, colours, a.holeEdges, static_cast<std::size_t>(options.maxHoleEdges));
    source.resize(tris.size(), kNone);
    if (cleanup.holesFilled) a = analyze(mesh);
  }
  if (!a.holeEdges.empty()) {
    std::string what = "open: " + counted(a.holes, "hole", "holes") + ", " +
                       counted(a.holeEdges.size(), "boundary edge", "boundary edges");
    if (a.components > 1)
      // Filling would close each piece on its own: the pieces need joining, not holes filling.
      what += " in " + std::to_string(a.components) +
              " pieces that share no vertices — weld coincident vertices (merge by distance) in "
              "a modelling tool";
    else if (!options.fillHoles)
      what += " — close them first (or try --fill-holes)";
    else
      what += " left after filling " + counted(cleanup.holesFilled, "hole", "holes") +
              " of at most " + std::to_string(options.maxHoleEdges) +
              " edges — close the rest in a modelling tool (or allow larger holes)";
    refuse(what);
  }
  if (a.pinchVertices)
    refuse("vertex " + std::to_string(std::uint64_t(a.firstPinch) + 1) +
           " is a pinch: its faces form " + std::to_string(a.firstPinchFans) +
           " separate fans — split it (or pull the touching parts apart) in a modelling tool" +
           (a.pinchVertices > 1 ? " (" + std::to_string(a.pinchVertices) + " pinch vertices in all)"
                                : std::string()));
  if (a.components > 1)
    refuse(std::to_string(a.components) +
           " components: only one closed surface can become a geometry image — keep the "
           "largest or split the file" +
           (cleanup.holesFilled ? std::string(" (if its faces were meant to touch, weld "
                                              "coincident vertices instead of filling holes)")
                                : std::string()));

  std::size_t vertexCount = 0;
  {
    std::vector<char> referenced(positions.size(), 0);
    for (const Tri& t : tris)
      for (const std::uint32_t v : t)
        referenced[v] = 1;
    vertexCount = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), 1));
  }
  const long long euler = static_cast<long long>(vertexCount) - static_cast<long long>(a.edges) +
                          static_cast<long long>(tris.size());
  if (euler != 2) {
    // One closed orientable component has χ = 2 − 2g, so χ is even and at most 2.
    const long long genus = (2 - euler) / 2;
    refuse("genus " + std::to_string(genus) + ": " + handles(genus) + " (Euler characteristic " +
           std::to_string(euler) +
           "); only genus-0 surfaces become an octahedral geometry image — close the handles in "
           "a modelling tool");
  }

  for (const Tri& t : tris) {
    const Vec3f p = positions[t[0]], q = positions[t[1]], r = positions[t[2]];
    // Exactly zero in double: these are collinear corners, not merely thin faces.
    const double ux = double(q.x) - p.x, uy = double(q.y) - p.y, uz = double(q.z) - p.z;
    const double vx = double(r.x) - p.x, vy = double(r.y) - p.y, vz = double(r.z) - p.z;
    if (uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0)
      ++cleanup.zeroAreaFacesKept;
  }

  const double volume = signedVolume(mesh);
  if (!(std::abs(volume) > 0) || !std::isfinite(volume))
    refuse("the surface encloses no volume (it is flat or folded onto itself) — it has no "
           "inside to unfold onto a sphere");
  if (volume < 0) {
    for (Tri& t : tris)
      std::swap(t[1], t[2]);
    cleanup.windingReversed = true;
  }

  std::vector<CornerUv> cornerUv;
  if (!attributes.cornerUv.empty())
    cornerUv = followCorners(tris, inputTris, attributes.cornerUv, source, positions.size());

  // Compact: drop every vertex no face refers to, keeping file order.
  std::vector<std::uint32_t> newIndex(positions.size(), kNone);
  for (const Tri& t : tris)
    for (const std::uint32_t v : t)
      newIndex[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (newIndex[v] == 0) {
      newIndex[v] = next;
      if (!colours.empty()) colours[next] = colours[v];
      positions[next++] = positions[v];
    }
  const std::size_t removed = positions.size() - next;
  positions.resize(next);
  if (!colours.empty()) colours.resize(next);
  for (Tri& t : tris)
    for (std::uint32_t& v : t)
      v = newIndex[v];
  cleanup.unusedVerticesRemoved = removed - cleanup.duplicateVerticesWelded;
  ValidatedMesh out;
  out.mesh = std::move(mesh);
  out.cleanup = cleanup;
  out.vertexColours = std::move(colours);
  out.cornerUv = std::move(cornerUv);
  return out;
}

} // namespace

ValidatedMesh loadGenus0Mesh(const fs::path& path, const ValidationOptions& options) {
  try {
    detail::RawMesh raw = detail::readRawMesh(path);
    ValidatedMesh out =
        validate(std::move(raw.mesh), {std::move(raw.vertexColours), std::move(raw.cornerUv)},
                 options, path.string() + ": ", raw.cornersPerFace, raw.shortFaces);
    out.diffuseTexture = std::move(raw.diffuseTexture);
    out.notes = std::move(raw.notes);
    return out;
  } catch (const std::bad_alloc&) {
    // The file, not --size, asked for the memory: say so (main's message is about --size).
    throw Error(ErrorKind::InvalidInput, path.string() +
                                             ": not enough memory to read this mesh: it is "
                                             "larger than this machine can hold");
  }
}

std::vector<ValidatedMesh> loadGenus0Parts(const fs::path& path, const ValidationOptions& options,
                                           std::size_t maxParts) {
  try {
    detail::RawMesh raw = detail::readRawMesh(path);
    std::vector<TriangleMesh> parts =
        detail::splitConnectedParts(raw.cornersPerFace ? detail::weldExactly(raw.mesh) : raw.mesh);
    if (parts.size() <= 1) {
      ValidatedMesh out =
          validate(std::move(raw.mesh), {std::move(raw.vertexColours), std::move(raw.cornerUv)},
                   options, path.string() + ": ", raw.cornersPerFace, raw.shortFaces);
      out.diffuseTexture = std::move(raw.diffuseTexture);
      out.notes = std::move(raw.notes);
      std::vector<ValidatedMesh> one;
      one.push_back(std::move(out));
      return one;
    }
    if (parts.size() > maxParts)
      throw Error(ErrorKind::InvalidInput,
                  path.string() + ": " + std::to_string(parts.size()) +
                      " separate parts; a document holds at most " + std::to_string(maxParts) +
                      " objects — join or delete parts in a modelling tool");
    std::vector<ValidatedMesh> result;
    result.reserve(parts.size());
    for (TriangleMesh& part : parts) {
      try {
        result.push_back(validate(std::move(part), {}, options, std::string(), false, 0));
      } catch (const Error&) {
        // A part that is no closed genus-0 lump by itself: the whole mesh's own refusal says
        // best what to do (pieces that need welding or joining, holes across the parts).
        validate(std::move(raw.mesh), {}, options, path.string() + ": ", raw.cornersPerFace,
                 raw.shortFaces);
        throw;
      }
      if (!raw.vertexColours.empty() || !raw.cornerUv.empty())
        result.back().notes.push_back("colours and texture coordinates are not carried when a "
                                      "mesh is split into parts");
    }
    return result;
  } catch (const std::bad_alloc&) {
    throw Error(ErrorKind::InvalidInput, path.string() +
                                             ": not enough memory to read this mesh: it is "
                                             "larger than this machine can hold");
  }
}

ValidatedMesh validateGenus0Mesh(TriangleMesh mesh, const ValidationOptions& options) {
  return validate(std::move(mesh), {}, options, std::string(), false, 0);
}

} // namespace octaclay::core
