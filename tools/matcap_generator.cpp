// Procedural matcaps: a unit sphere seen head-on under fixed lights, one closed-form shading per
// material (wrapped Lambert for the soft ones, Blinn–Phong highlights, a reflected studio for
// chrome). Only sqrt, pow and arithmetic: nothing a libm rounds differently by more than a step.

#include "matcap_generator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace octaclay::tools {

namespace {

constexpr int kMatcapSize = 256;

struct V3 {
  float x, y, z;
};

V3 operator+(V3 a, V3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V3 operator*(V3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
float dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 normalized(V3 a) {
  return a * (1.0f / std::sqrt(dot(a, a)));
}
V3 mix(V3 a, V3 b, float t) {
  return a * (1.0f - t) + b * t;
}
float clamp01(float x) {
  return std::clamp(x, 0.0f, 1.0f);
}
float smoothstep(float edge0, float edge1, float x) {
  const float t = clamp01((x - edge0) / (edge1 - edge0));
  return t * t * (3.0f - 2.0f * t);
}

const V3 kView{0, 0, 1};
const V3 kKey = normalized({-0.55f, 0.6f, 0.6f}); // upper left, in front
const V3 kFill = normalized({0.75f, -0.15f, 0.65f});

// Lambert wrapped by w (0: plain), so light reaches past the terminator as through wax or skin.
float wrapped(V3 n, V3 light, float w) {
  return clamp01((dot(n, light) + w) / (1.0f + w));
}

float highlight(V3 n, V3 light, float power) {
  return std::pow(clamp01(dot(n, normalized(light + kView))), power);
}

V3 clay(V3 n) {
  const V3 base{0.78f, 0.71f, 0.64f};
  const float light = 0.2f + 0.75f * wrapped(n, kKey, 0.25f) + 0.18f * wrapped(n, kFill, 0.0f);
  return base * light + V3{1, 1, 1} * (0.1f * highlight(n, kKey, 16.0f));
}

V3 redWax(V3 n) {
  const V3 base{0.66f, 0.06f, 0.05f};
  const float d = std::pow(wrapped(n, kKey, 0.6f), 1.4f);
  const V3 glow = V3{0.95f, 0.3f, 0.12f} * (0.3f * std::pow(1.0f - n.z, 2.0f)); // light through
  return base * (0.16f + 0.95f * d + 0.15f * wrapped(n, kFill, 0.3f)) + glow +
         V3{1.0f, 0.93f, 0.88f} * (0.55f * highlight(n, kKey, 70.0f));
}

// The studio chrome mirrors: a bright sky over a sharp horizon and a dark floor, a softbox.
V3 chrome(V3 n) {
  const V3 r = n * (2.0f * n.z) + kView * -1.0f; // reflect(-view, n)
  V3 c;
  if (r.y >= 0)
    c = mix(V3{0.92f, 0.94f, 0.97f}, V3{0.32f, 0.42f, 0.58f}, std::sqrt(r.y));
  else
    c = mix(V3{0.3f, 0.27f, 0.25f}, V3{0.05f, 0.05f, 0.06f}, std::pow(-r.y, 0.4f));
  const float box = smoothstep(0.93f, 0.97f, dot(r, kKey));
  const float strip = smoothstep(0.9f, 0.95f, dot(r, normalized({0.85f, 0.3f, 0.45f})));
  return mix(c, V3{1, 1, 1}, std::max(box, 0.7f * strip)) * 0.95f;
}

V3 skin(V3 n) {
  const V3 base{0.88f, 0.65f, 0.54f};
  const float d = wrapped(n, kKey, 0.45f);
  // Subsurface scattering reddens the shadow side of the terminator.
  const float scatter = smoothstep(0.0f, 0.35f, d) * (1.0f - smoothstep(0.35f, 0.8f, d));
  const float fresnel = std::pow(1.0f - n.z, 3.0f);
  return base * (0.18f + 0.8f * d + 0.12f * wrapped(n, kFill, 0.2f)) +
         V3{0.5f, 0.1f, 0.06f} * (0.25f * scatter) + V3{0.9f, 0.85f, 0.85f} * (0.2f * fresnel) +
         V3{1, 1, 1} * (0.12f * highlight(n, kKey, 28.0f));
}

using Shade = V3 (*)(V3);
struct MatcapSpec {
  const char* id;
  Shade shade;
};
constexpr std::array<MatcapSpec, 4> kMatcaps{{
    {"clay", clay},
    {"red-wax", redWax},
    {"chrome", chrome},
    {"skin", skin},
}};

} // namespace

std::vector<std::string> generatedMatcapIds() {
  std::vector<std::string> ids;
  for (const MatcapSpec& spec : kMatcaps)
    ids.emplace_back(spec.id);
  return ids;
}

core::RasterImage generateMatcap(std::string_view id, int size) {
  const auto found = std::find_if(kMatcaps.begin(), kMatcaps.end(),
                                  [&](const MatcapSpec& s) { return id == s.id; });
  if (found == kMatcaps.end())
    throw std::invalid_argument("no generated matcap " + std::string(id));
  if (size < 16) throw std::invalid_argument("a matcap needs at least 16 texels a side");
  core::RasterImage image{size, size, 3, {}};
  image.pixels.reserve(static_cast<std::size_t>(size) * size * 3);
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      float x = (static_cast<float>(px) + 0.5f) / static_cast<float>(size) * 2.0f - 1.0f;
      float y = 1.0f - (static_cast<float>(py) + 0.5f) / static_cast<float>(size) * 2.0f;
      const float r2 = x * x + y * y;
      if (r2 > 0.998f) { // outside the disc: the rim's colour
        const float s = std::sqrt(0.998f / r2);
        x *= s;
        y *= s;
      }
      const V3 c = found->shade({x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))});
      image.pixels.insert(image.pixels.end(), {clamp01(c.x), clamp01(c.y), clamp01(c.z)});
    }
  return image;
}

void writeMatcaps(const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  for (const MatcapSpec& spec : kMatcaps)
    core::writePng(generateMatcap(spec.id, kMatcapSize), folder / (std::string(spec.id) + ".png"));
}

} // namespace octaclay::tools
