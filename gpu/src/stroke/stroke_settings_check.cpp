#include "stroke_settings_check.h"

#include "value_text.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/stroke_rules.h"

namespace octaclay::gpu::detail {
namespace {

void checkParameter(const BrushParameter& p, const std::array<float, 4>& v) {
  const std::string name = "parameter '" + p.id + "'";
  const std::size_t used = p.type == ParameterType::Color ? 4 : 1;
  for (std::size_t c = 0; c < used; ++c)
    requireFinite(name.c_str(), v[c]);
  if (p.type == ParameterType::Material) return; // an index into the engine's materials
  for (std::size_t c = 0; c < used; ++c)
    if (!(v[c] >= p.min && v[c] <= p.max))
      badSetting(name + " = " + valueText(v[c]) + " is outside [" + valueText(p.min) + ", " +
                 valueText(p.max) + "]");
}

} // namespace

void checkSettings(const BrushManifest& brush, const StrokeSettings& settings) {
  for (const auto& [id, value] : settings.parameters)
    if (const BrushParameter* p = brush.parameter(id)) checkParameter(*p, value);
  if (settings.viewEye) {
    requireFinite("the view's x", settings.viewEye->x);
    requireFinite("the view's y", settings.viewEye->y);
    requireFinite("the view's z", settings.viewEye->z);
  }
  requireFinite("the spacing", settings.spacing);
}

[[noreturn]] void badSetting(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

} // namespace octaclay::gpu::detail
