#pragma once

#include <optional>
#include <string_view>

namespace octaclay::core {

/// How an object's geometry image closes up (DESIGN.md, "Objects and topologies"): its
/// neighbours across the image's edges, its seams and its Euler characteristic.
enum class Topology {
  Octahedral, ///< closed genus 0: the octahedral ball, folded seams on the image's edges
  Torus,      ///< closed genus 1: periodic in both directions, no folds
  Plane,      ///< an open sheet with one boundary loop, no seams
};

/// The name stored in files and typed on the command line: "octahedral", "torus", "plane".
std::string_view topologyName(Topology topology);
/// The topology named so, or nothing for any other text.
std::optional<Topology> parseTopology(std::string_view name);

} // namespace octaclay::core
