#include "brush_value_store.h"

#include "octaclay/gpu/stroke.h"

#include <QSettings>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

namespace octaclay::app {
namespace {

QString toQString(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// The enum value whose manifest name is `name`, if any.
template <typename Enum, std::size_t N> std::optional<Enum> fromManifestName(const QString& name) {
  for (std::size_t k = 0; k < N; ++k) {
    const auto value = static_cast<Enum>(k);
    if (name == toQString(gpu::toManifestName(value))) return value;
  }
  return std::nullopt;
}

// value fitted to the parameter's type and range; the default where it makes no sense.
std::array<float, 4> fitParameter(const gpu::BrushParameter& parameter, std::array<float, 4> v) {
  const std::array<float, 4>& d = parameter.defaultValue;
  switch (parameter.type) {
  case gpu::ParameterType::Float:
    return {clampFinite(v[0], parameter.min, parameter.max, d[0]), 0.0f, 0.0f, 0.0f};
  case gpu::ParameterType::Int:
  case gpu::ParameterType::Enum:
    return {std::isfinite(v[0]) ? std::clamp(std::round(v[0]), parameter.min, parameter.max) : d[0],
            0.0f, 0.0f, 0.0f};
  case gpu::ParameterType::Bool:
    return {std::isfinite(v[0]) ? (v[0] != 0.0f ? 1.0f : 0.0f) : d[0], 0.0f, 0.0f, 0.0f};
  case gpu::ParameterType::Color:
    for (std::size_t c = 0; c < 4; ++c)
      v[c] = clampFinite(v[c], 0.0f, 1.0f, d[c]);
    return v;
  case gpu::ParameterType::Material: // an index into the installed materials
    return {std::isfinite(v[0]) && v[0] >= 0 ? std::round(v[0]) : d[0], 0.0f, 0.0f, 0.0f};
  }
  return d;
}

void fitValues(const gpu::BrushManifest& brush, BrushValues& values) {
  values.radius = clampFinite(values.radius, kMinRadius, kMaxRadius, BrushValues{}.radius);
  values.radiusPixels =
      clampFinite(values.radiusPixels, kMinRadiusPixels, kMaxRadiusPixels, kDefaultRadiusPixels);
  values.strength = clampFinite(values.strength, 0.0f, 1.0f, BrushValues{}.strength);
  if (values.falloff == gpu::Falloff::Curve && brush.falloffCurve.empty())
    values.falloff = brush.falloff;
  std::map<std::string, std::array<float, 4>> parameters;
  for (const gpu::BrushParameter& p : brush.parameters) {
    const auto known = values.parameters.find(p.id);
    parameters[p.id] =
        known != values.parameters.end() ? fitParameter(p, known->second) : p.defaultValue;
  }
  values.parameters = std::move(parameters);
}

QString settingsGroup(const QString& id) {
  return QStringLiteral("brushes/") + id;
}

} // namespace

RadiusUnit BrushValueStore::loadRadiusUnit() {
  QSettings settings;
  const QString stored = settings.value(QStringLiteral("brushes/radiusUnit")).toString();
  if (stored == QStringLiteral("view")) return RadiusUnit::View;
  if (stored == QStringLiteral("scene")) return RadiusUnit::Scene;
  settings.beginGroup(QStringLiteral("brushes"));
  return settings.childGroups().isEmpty() ? RadiusUnit::View : RadiusUnit::Scene;
}

void BrushValueStore::saveRadiusUnit(RadiusUnit unit) {
  QSettings().setValue(QStringLiteral("brushes/radiusUnit"),
                       unit == RadiusUnit::View ? QStringLiteral("view") : QStringLiteral("scene"));
}

namespace {
constexpr std::array kPressureNames{"none", "radius", "strength"};
constexpr unsigned kSymmetryBits = gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ;
} // namespace

void BrushValueStore::loadStrokeOptions(BrushSettings& out) {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  const QString pressure = settings.value(QStringLiteral("pressureTarget")).toString();
  for (std::size_t k = 0; k < kPressureNames.size(); ++k)
    if (pressure == QLatin1String(kPressureNames[k]))
      out.pressureTarget = static_cast<PressureTarget>(k);
  bool ok = false;
  if (const int percent = settings.value(QStringLiteral("stabilizer")).toInt(&ok); ok)
    out.stabilizer = static_cast<float>(std::clamp(percent, 0, 100)) / 100.0f;
  if (const uint axes = settings.value(QStringLiteral("symmetry")).toUInt(&ok); ok)
    out.symmetry = axes & kSymmetryBits;
  if (const QVariant keep = settings.value(QStringLiteral("keepDetail")); keep.isValid())
    out.keepDetail = keep.toBool();
}

void BrushValueStore::saveStrokeOptions(const BrushSettings& s) {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  settings.setValue(
      QStringLiteral("pressureTarget"),
      QString::fromLatin1(kPressureNames[static_cast<std::size_t>(s.pressureTarget)]));
  settings.setValue(QStringLiteral("stabilizer"),
                    static_cast<int>(std::lround(s.stabilizer * 100.0f)));
  settings.setValue(QStringLiteral("symmetry"), s.symmetry);
  settings.setValue(QStringLiteral("keepDetail"), s.keepDetail);
}

float clampFinite(float value, float lo, float hi, float fallback) {
  return std::isfinite(value) ? std::clamp(value, lo, hi) : fallback;
}

void BrushValueStore::setBrushes(const std::vector<gpu::BrushManifest>& brushes) {
  std::map<QString, BrushValues> values;
  for (const gpu::BrushManifest& brush : brushes) {
    const QString id = QString::fromStdString(brush.id);
    if (values.count(id) != 0) continue; // a duplicate id: the first one wins
    const auto known = values_.find(id);
    BrushValues v = known != values_.end() ? known->second : load(brush);
    fitValues(brush, v);
    values.emplace(id, std::move(v));
  }
  values_ = std::move(values);
}

BrushValues* BrushValueStore::find(const QString& id) {
  const auto it = values_.find(id);
  return it != values_.end() ? &it->second : nullptr;
}

const BrushValues* BrushValueStore::find(const QString& id) const {
  const auto it = values_.find(id);
  return it != values_.end() ? &it->second : nullptr;
}

BrushValues BrushValueStore::defaults(const gpu::BrushManifest& brush) const {
  BrushValues v;
  if (brush.category == gpu::Category::Sculpt) {
    const bool drags =
        brush.stroke == gpu::StrokeKind::Drag || brush.stroke == gpu::StrokeKind::Anchored;
    v.strength = drags ? kDefaultDragStrength : kDefaultSculptStrength;
  }
  v.falloff = brush.falloff;
  v.area = brush.area;
  for (const gpu::BrushParameter& p : brush.parameters) {
    v.parameters[p.id] = p.defaultValue;
    if (p.type == gpu::ParameterType::Material)
      v.parameters[p.id][0] = static_cast<float>(
          std::max<qsizetype>(0, materials_.indexOf(QString::fromStdString(p.options.front()))));
  }
  return v;
}

BrushValues BrushValueStore::load(const gpu::BrushManifest& brush) const {
  BrushValues v = defaults(brush);
  QSettings settings;
  settings.beginGroup(settingsGroup(QString::fromStdString(brush.id)));
  bool ok = false;
  if (const float r = settings.value(QStringLiteral("radius")).toFloat(&ok); ok) v.radius = r;
  if (const float r = settings.value(QStringLiteral("radiusPixels")).toFloat(&ok); ok)
    v.radiusPixels = r;
  if (const float s = settings.value(QStringLiteral("strength")).toFloat(&ok); ok) v.strength = s;
  if (const auto falloff =
          fromManifestName<gpu::Falloff, 4>(settings.value(QStringLiteral("falloff")).toString()))
    v.falloff = *falloff;
  if (const auto area =
          fromManifestName<gpu::AreaMode, 3>(settings.value(QStringLiteral("area")).toString()))
    v.area = *area;

  settings.beginGroup(QStringLiteral("parameters"));
  for (const gpu::BrushParameter& p : brush.parameters) {
    const QString key = QString::fromStdString(p.id);
    if (!settings.contains(key)) continue;
    const QVariant stored = settings.value(key);
    std::array<float, 4>& value = v.parameters[p.id];
    switch (p.type) {
    case gpu::ParameterType::Float:
    case gpu::ParameterType::Int:
      if (const float f = stored.toFloat(&ok); ok) value[0] = f;
      break;
    case gpu::ParameterType::Bool:
      value[0] = stored.toBool() ? 1.0f : 0.0f;
      break;
    case gpu::ParameterType::Color: {
      const QStringList channels = stored.toStringList();
      if (channels.size() != 4) break;
      std::array<float, 4> color{};
      bool all = true;
      for (std::size_t c = 0; c < 4; ++c) {
        color[c] = channels[static_cast<qsizetype>(c)].toFloat(&ok);
        all = all && ok;
      }
      if (all) value = color;
      break;
    }
    case gpu::ParameterType::Enum: {
      const auto option =
          std::find(p.options.begin(), p.options.end(), stored.toString().toStdString());
      if (option != p.options.end()) value[0] = static_cast<float>(option - p.options.begin());
      break;
    }
    case gpu::ParameterType::Material: // stored by id: the installed materials may change
      if (const qsizetype index = materials_.indexOf(stored.toString()); index >= 0)
        value[0] = static_cast<float>(index);
      break;
    }
  }
  return v;
}

void BrushValueStore::save(const gpu::BrushManifest& brush) const {
  const QString id = QString::fromStdString(brush.id);
  const auto it = values_.find(id);
  if (it == values_.end()) return;
  const BrushValues& v = it->second;
  QSettings settings;
  settings.beginGroup(settingsGroup(id));
  settings.setValue(QStringLiteral("radius"), static_cast<double>(v.radius));
  settings.setValue(QStringLiteral("radiusPixels"), static_cast<double>(v.radiusPixels));
  settings.setValue(QStringLiteral("strength"), static_cast<double>(v.strength));
  settings.setValue(QStringLiteral("falloff"), toQString(gpu::toManifestName(v.falloff)));
  settings.setValue(QStringLiteral("area"), toQString(gpu::toManifestName(v.area)));
  settings.beginGroup(QStringLiteral("parameters"));
  for (const gpu::BrushParameter& p : brush.parameters) {
    const auto value = v.parameters.find(p.id);
    if (value == v.parameters.end()) continue;
    const std::array<float, 4>& x = value->second;
    const QString key = QString::fromStdString(p.id);
    switch (p.type) {
    case gpu::ParameterType::Float:
      settings.setValue(key, static_cast<double>(x[0]));
      break;
    case gpu::ParameterType::Int:
      settings.setValue(key, static_cast<int>(std::lround(x[0])));
      break;
    case gpu::ParameterType::Bool:
      settings.setValue(key, x[0] != 0.0f);
      break;
    case gpu::ParameterType::Color: {
      // Decimal text rather than a QColor: exact floats, and readable in the settings file.
      QStringList channels;
      for (const float c : x)
        channels.append(QString::number(static_cast<double>(c), 'g', 9));
      settings.setValue(key, channels);
      break;
    }
    case gpu::ParameterType::Enum: {
      // The option's name, so a manifest that reorders its options keeps the user's choice.
      const auto index = static_cast<std::size_t>(std::lround(x[0]));
      if (index < p.options.size())
        settings.setValue(key, QString::fromStdString(p.options[index]));
      break;
    }
    case gpu::ParameterType::Material: {
      const auto index = static_cast<qsizetype>(std::lround(x[0]));
      if (index >= 0 && index < materials_.size()) settings.setValue(key, materials_[index]);
      break;
    }
    }
  }
}

} // namespace octaclay::app
