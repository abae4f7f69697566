#include "brush_state.h"

#include "octaclay/gpu/stroke.h"

#include <cmath>
#include <set>

namespace octaclay::app {

BrushState::BrushState(QObject* parent) : QObject(parent) {
  options_.radiusUnit = BrushValueStore::loadRadiusUnit();
  BrushValueStore::loadStrokeOptions(options_);
}

void BrushState::setBrushes(std::vector<gpu::BrushManifest> brushes,
                            std::vector<std::string> errors) {
  brushes_ = std::move(brushes);
  errors_ = std::move(errors);
  store_.setBrushes(brushes_); // a duplicate id: the first one wins, as in currentBrush
  const QStringList ids = brushIds();
  if (!ids.contains(currentId_))
    currentId_ = ids.contains(QStringLiteral("push")) ? QStringLiteral("push") : ids.value(0);
  emit brushesChanged();
  emit brushSelected();
  emit changed();
}

QStringList BrushState::errors() const {
  QStringList out;
  for (const std::string& e : errors_)
    out.append(QString::fromStdString(e));
  return out;
}

void BrushState::setMaterials(QStringList ids) {
  if (ids == store_.materials()) return;
  store_.setMaterials(std::move(ids));
  emit brushesChanged();
}

QStringList BrushState::brushIds() const {
  QStringList ids;
  std::set<std::string> seen;
  for (const gpu::Category category :
       {gpu::Category::Sculpt, gpu::Category::Paint, gpu::Category::Splat})
    for (const gpu::BrushManifest& brush : brushes_)
      if (brush.category == category && seen.insert(brush.id).second)
        ids.append(QString::fromStdString(brush.id));
  return ids;
}

const gpu::BrushManifest* BrushState::currentBrush() const {
  if (currentId_.isEmpty()) return nullptr;
  const std::string key = currentId_.toStdString();
  for (const gpu::BrushManifest& brush : brushes_)
    if (brush.id == key) return &brush;
  return nullptr;
}

bool BrushState::selectBrush(const QString& id) {
  if (id.isEmpty() || !brushIds().contains(id)) return false;
  if (id == currentId_) return true;
  currentId_ = id;
  emit brushSelected();
  emit changed();
  return true;
}

const BrushValues& BrushState::values() const {
  const BrushValues* values = store_.find(currentId_);
  return values ? *values : noBrush_;
}

BrushValues& BrushState::currentValues() {
  BrushValues* values = store_.find(currentId_);
  return values ? *values : noBrush_;
}

void BrushState::setRadius(float fractionOfDiagonal) {
  const float r = clampFinite(fractionOfDiagonal, kMinRadius, kMaxRadius, radius());
  if (r == radius()) return;
  currentValues().radius = r;
  valuesEdited();
}

void BrushState::setRadiusPixels(float pixels) {
  const float r = clampFinite(pixels, kMinRadiusPixels, kMaxRadiusPixels, radiusPixels());
  if (r == radiusPixels()) return;
  currentValues().radiusPixels = r;
  valuesEdited();
}

void BrushState::setRadiusUnit(RadiusUnit unit) {
  if (unit == options_.radiusUnit) return;
  options_.radiusUnit = unit;
  BrushValueStore::saveRadiusUnit(unit);
  emit changed();
}

void BrushState::setRadiusInUnit(float value) {
  radiusUnit() == RadiusUnit::View ? setRadiusPixels(value) : setRadius(value);
}

float BrushState::radiusInUnit() const {
  return radiusUnit() == RadiusUnit::View ? radiusPixels() : radius();
}

void BrushState::setStrength(float strength) {
  const float s = clampFinite(strength, 0.0f, 1.0f, this->strength());
  if (s == this->strength()) return;
  currentValues().strength = s;
  valuesEdited();
}

void BrushState::setFalloff(gpu::Falloff falloff) {
  const gpu::BrushManifest* brush = currentBrush();
  if (falloff == values().falloff ||
      (falloff == gpu::Falloff::Curve && (!brush || brush->falloffCurve.empty())))
    return;
  currentValues().falloff = falloff;
  valuesEdited();
}

void BrushState::setArea(gpu::AreaMode area) {
  if (area == values().area) return;
  currentValues().area = area;
  valuesEdited();
}

void BrushState::setParameter(const std::string& id, std::array<float, 4> value) {
  auto& parameters = currentValues().parameters;
  const auto it = parameters.find(id);
  if (it == parameters.end() || it->second == value) return;
  it->second = value;
  valuesEdited();
}

void BrushState::setPressureTarget(PressureTarget target) {
  if (target == options_.pressureTarget) return;
  options_.pressureTarget = target;
  optionsEdited();
}

void BrushState::setStabilizer(float amount) {
  const float percent = std::round(clampFinite(amount, 0.0f, 1.0f, 0.0f) * 100.0f);
  if (percent / 100.0f == options_.stabilizer) return;
  options_.stabilizer = percent / 100.0f;
  optionsEdited();
}

void BrushState::setSymmetry(unsigned axes) {
  axes &= gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ;
  if (axes == options_.symmetry) return;
  options_.symmetry = axes;
  optionsEdited();
}

void BrushState::setKeepDetail(bool on) {
  if (on == options_.keepDetail) return;
  options_.keepDetail = on;
  optionsEdited();
}

BrushSettings BrushState::settings() const {
  const BrushValues& v = values();
  BrushSettings s = options_;
  s.brushId = currentId_.toStdString();
  s.radius = v.radius;
  s.radiusPixels = v.radiusPixels;
  s.strength = v.strength;
  s.falloff = v.falloff;
  s.area = v.area;
  s.parameters = v.parameters;
  return s;
}

void BrushState::setPaintTarget(core::EditLayer layer) {
  if (layer == paintTarget_) return;
  paintTarget_ = layer;
  emit changed();
}

void BrushState::valuesEdited() {
  if (const gpu::BrushManifest* brush = currentBrush()) store_.save(*brush);
  emit changed();
}

void BrushState::optionsEdited() {
  BrushValueStore::saveStrokeOptions(options_);
  emit changed();
}

} // namespace octaclay::app
