#pragma once

// Issue 23's creature, shared by bench_creature and keep_detail_test: four legs and a neck pulled
// out of a ball with snake-hook, each one stroke along a 3-point path (where it starts on the
// ball, then two object-space points the drag moves through), and each part's share of samples.

#include "stroke_script.h"

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/measure/stretch.h"

#include <array>
#include <string>
#include <vector>

namespace octaclay::testing {

struct CreaturePart {
  const char* name;
  core::Vec3f start;               ///< direction from the ball's centre to where it starts
  std::array<core::Vec3f, 2> drag; ///< the two points the drag moves through
  float radius;                    ///< object units
};

/// Where the parts are pulled from. Animal: the modeller's up is +y and its front +z, so the
/// legs come out of the ball's lower half, the front pair on its +z half (the octahedral image's
/// middle) and the back pair on its -z half (the image's corner triangles, across seams), and
/// the neck rises forward. LegsMinusZ / LegsPlusZ: all four legs along -z / +z, the neck the
/// other way and to +x.
enum class CreatureLayout { Animal, LegsMinusZ, LegsPlusZ };

inline const char* layoutName(CreatureLayout layout) {
  return layout == CreatureLayout::Animal       ? "animal"
         : layout == CreatureLayout::LegsMinusZ ? "legs -z"
                                                : "legs +z";
}

inline std::vector<CreaturePart> creatureParts(CreatureLayout layout) {
  using core::Vec3f;
  const bool animal = layout == CreatureLayout::Animal;
  const Vec3f down = animal                                 ? Vec3f{0, -1, 0}
                     : layout == CreatureLayout::LegsMinusZ ? Vec3f{0, 0, -1}
                                                            : Vec3f{0, 0, 1};
  std::vector<CreaturePart> out;
  for (const float x : {-1.0f, 1.0f})
    for (const float y : {-1.0f, 1.0f}) {
      // a, b: the leg's sideways axes (b from back to front).
      const Vec3f a{x, 0, 0}, b = animal ? Vec3f{0, 0, y} : Vec3f{0, y, 0};
      const Vec3f s = core::normalize(a * 0.45f + b * 0.45f + down * 0.77f);
      out.push_back(
          {y > 0 ? (x > 0 ? "leg front left" : "leg front right")
                 : (x > 0 ? "leg back left" : "leg back right"),
           s,
           {s + a * 0.05f + b * 0.05f + down * 0.45f, s + a * 0.08f + b * 0.08f + down * 0.9f},
           0.2f});
    }
  const Vec3f up = down * -1.0f, front = animal ? Vec3f{0, 0, 1} : Vec3f{1, 0, 0};
  out.push_back({"neck",
                 core::normalize(front * 0.7f + up * 0.7f),
                 {front * 0.95f + up * 1.15f, front * 1.25f + up * 1.55f},
                 0.25f});
  return out;
}

/// The snake-hook stroke that pulls part out of ball: from ball's sample nearest to the part's
/// start through its drag points, at full strength, through the session's door (playStroke);
/// diagonal is the model's as the stroke begins (SculptSession::diagonal), which turns the part's
/// radius into the session's unit.
inline app::StrokeScript creatureStroke(const CreaturePart& part, const core::GeometryImage& ball,
                                        const std::string& brushId, float diagonal) {
  const int n = ball.size();
  float best = 1e30f;
  std::array<float, 2> uv{};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (const float d = core::length(ball.at(i, j).xyz() - part.start); d < best)
        best = d, uv = {float(i) / float(n), float(j) / float(n)};
  app::StrokeScript s;
  s.start.brushId = s.start.settings.brushId = brushId;
  s.start.settings.radius = part.radius / diagonal;
  s.start.settings.strength = 1.0f;
  s.path = {uv};
  s.dragPoints = {part.drag[0], part.drag[1]};
  return s;
}

/// Which part a surface point belongs to: the one whose start is nearest, once it is farther
/// than 1.15 from the centre (out of the ball); -1 on the body.
inline int creaturePartOf(const std::vector<CreaturePart>& parts, const core::Vec3f& p) {
  if (core::length(p) <= 1.15f) return -1;
  int best = 0;
  for (std::size_t k = 1; k < parts.size(); ++k)
    if (core::length(p - parts[k].start) < core::length(p - parts[std::size_t(best)].start))
      best = int(k);
  return best;
}

/// Each part's share of the samples against its share of the area.
inline std::vector<core::RegionSampling> creatureSampling(const core::GeometryImage& image,
                                                          const std::vector<CreaturePart>& parts) {
  std::vector<core::RegionSampling> out;
  for (std::size_t k = 0; k < parts.size(); ++k)
    out.push_back(core::regionSampling(
        image, [&](const core::Vec3f& p) { return creaturePartOf(parts, p) == int(k); }));
  return out;
}

} // namespace octaclay::testing
