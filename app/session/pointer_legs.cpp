#include "pointer_legs.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace octaclay::app {

namespace {

// The ball's border: (u, 0) is (1 − u, 0), (u, 1) is (1 − u, 1), (0, v) is (0, 1 − v) and
// (1, v) is (1, 1 − v) (core::wrap's octahedral tiling). Past an edge, b stands where the
// tiling's half-turn about that edge puts it; the edge whose image of b lies nearest a is the
// one crossed: walked to it, continued from its other side. A pointer that jumped farther
// (over a corner, or off and back onto the model) jumps.
std::vector<PointerLeg> ballLegs(core::Vec2f a, core::Vec2f b) {
  struct Edge {
    core::Vec2f beyond; // b as seen across the edge
    bool alongU;        // the edge is v = value (else u = value)
    float value;
  };
  const Edge edges[] = {{{1 - b.x, -b.y}, true, 0.0f},
                        {{1 - b.x, 2 - b.y}, true, 1.0f},
                        {{-b.x, 1 - b.y}, false, 0.0f},
                        {{2 - b.x, 1 - b.y}, false, 1.0f}};
  const Edge* best = nullptr;
  float nearest = 0.25f;
  for (const Edge& e : edges) {
    const float d = std::max(std::abs(e.beyond.x - a.x), std::abs(e.beyond.y - a.y));
    if (d < nearest) nearest = d, best = &e;
  }
  if (!best) return {{true, b, b}};
  const float from = best->alongU ? a.y : a.x, to = best->alongU ? best->beyond.y : best->beyond.x;
  const float t = to != from ? std::clamp((best->value - from) / (to - from), 0.0f, 1.0f) : 0.0f;
  const core::Vec2f onEdge{std::clamp(a.x + t * (best->beyond.x - a.x), 0.0f, 1.0f),
                           std::clamp(a.y + t * (best->beyond.y - a.y), 0.0f, 1.0f)};
  const core::Vec2f across = best->alongU ? core::Vec2f{1 - onEdge.x, best->value}
                                          : core::Vec2f{best->value, 1 - onEdge.y};
  const core::Vec2f edgeHere =
      best->alongU ? core::Vec2f{onEdge.x, best->value} : core::Vec2f{best->value, onEdge.y};
  return {{false, a, edgeHere}, {true, across, b}};
}

} // namespace

std::vector<PointerLeg> pointerLegs(core::Topology topology, core::Vec2f a, core::Vec2f b) {
  const float du = b.x - a.x, dv = b.y - a.y;
  if (topology == core::Topology::Octahedral) {
    if (std::abs(du) <= 0.25f && std::abs(dv) <= 0.25f) return {{false, a, b}};
    return ballLegs(a, b);
  }
  if (topology != core::Topology::Torus || (std::abs(du) <= 0.5f && std::abs(dv) <= 0.5f))
    return {{false, a, b}};
  // The torus: the end moved by a period where that is nearer, then the straight segment in the
  // unwrapped plane cut where it crosses u or v = 0 or 1.
  const core::Vec2f end{b.x + (du > 0.5f    ? -1.0f
                               : du < -0.5f ? 1.0f
                                            : 0.0f),
                        b.y + (dv > 0.5f    ? -1.0f
                               : dv < -0.5f ? 1.0f
                                            : 0.0f)};
  std::vector<float> cuts{0.0f, 1.0f};
  for (const auto& [from, to] : {std::pair{a.x, end.x}, std::pair{a.y, end.y}})
    for (const float edge : {0.0f, 1.0f})
      if ((from - edge) * (to - edge) < 0) cuts.push_back((edge - from) / (to - from));
  std::sort(cuts.begin(), cuts.end());
  const auto at = [&](float t) {
    return core::Vec2f{a.x + t * (end.x - a.x), a.y + t * (end.y - a.y)};
  };
  std::vector<PointerLeg> legs;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const core::Vec2f p = at(cuts[k]), q = at(cuts[k + 1]);
    const core::Vec2f mid = at(0.5f * (cuts[k] + cuts[k + 1]));
    // The period this leg lies in: its midpoint's.
    const float su = std::floor(mid.x), sv = std::floor(mid.y);
    const core::Vec2f from{std::clamp(p.x - su, 0.0f, 1.0f), std::clamp(p.y - sv, 0.0f, 1.0f)};
    const core::Vec2f to{std::clamp(q.x - su, 0.0f, 1.0f), std::clamp(q.y - sv, 0.0f, 1.0f)};
    legs.push_back({k > 0, from, to});
  }
  return legs;
}

int walkPointer(gpu::StrokeSession& stroke, core::Topology topology,
                std::optional<std::array<float, 2>> last, core::Vec2f b, float radius,
                float strength) {
  if (!last) return stroke.moveToUv(b, radius, strength, 1.0f);
  int made = 0;
  for (const PointerLeg& leg : pointerLegs(topology, {(*last)[0], (*last)[1]}, b)) {
    if (leg.jumped) stroke.continueFrom(leg.from);
    made += stroke.moveToUv(leg.to, radius, strength, 1.0f);
  }
  return made;
}

} // namespace octaclay::app
