#include "octaclay/core/geometry/topology.h"

namespace octaclay::core {

std::string_view topologyName(Topology topology) {
  switch (topology) {
  case Topology::Torus:
    return "torus";
  case Topology::Plane:
    return "plane";
  case Topology::Octahedral:
    break;
  }
  return "octahedral";
}

std::optional<Topology> parseTopology(std::string_view name) {
  for (Topology t : {Topology::Octahedral, Topology::Torus, Topology::Plane})
    if (topologyName(t) == name) return t;
  return std::nullopt;
}

} // namespace octaclay::core
