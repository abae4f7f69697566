// The Brushes dock panel. The panel owns the brushes' values (store_); widgets only
// show and edit them, so setters never depend on a widget's rounding (a spin box with one
// decimal still hands back the exact radius given to setRadius).

#include "brush_panel.h"

#include "brush_list.h"
#include "parameter_form.h"
#include "radius_field.h"
#include "stroke_options_box.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

namespace {

QString falloffTitle(gpu::Falloff falloff) {
  switch (falloff) {
  case gpu::Falloff::Linear:
    return BrushPanel::tr("Linear");
  case gpu::Falloff::Smooth:
    return BrushPanel::tr("Smooth");
  case gpu::Falloff::Constant:
    return BrushPanel::tr("Constant");
  case gpu::Falloff::Curve:
    return BrushPanel::tr("Curve (from the brush)");
  }
  return {};
}

QString areaTitle(gpu::AreaMode area) {
  switch (area) {
  case gpu::AreaMode::Uv:
    return BrushPanel::tr("Texture space (uv)");
  case gpu::AreaMode::Volume:
    return BrushPanel::tr("Sphere (volume)");
  case gpu::AreaMode::VolumeNormal:
    return BrushPanel::tr("Sphere, facing side (volume+normal)");
  }
  return {};
}

} // namespace

// ---------------------------------------------------------------------------------------------

BrushPanel::BrushPanel(QWidget* parent)
    : QWidget(parent), radiusUnit_(BrushValueStore::loadRadiusUnit()) {
  brushList_ = new QTreeWidget;
  brushList_->setObjectName(QStringLiteral("brushList"));
  brushList_->setHeaderHidden(true);
  brushList_->setRootIsDecorated(false);
  brushList_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(brushList_, &QTreeWidget::itemSelectionChanged, this, [this] {
    const QList<QTreeWidgetItem*> selected = brushList_->selectedItems();
    if (!selected.isEmpty()) onCurrentItemChanged(selected.front());
  });

  errorFrame_ = new QFrame;
  errorFrame_->setObjectName(QStringLiteral("brushErrors"));
  errorFrame_->setStyleSheet(
      QStringLiteral("#brushErrors { background: rgba(211, 47, 47, 28); border: 1px solid "
                     "#d32f2f; border-radius: 3px; } #brushErrors QLabel { color: #c62828; }"));
  errorLayout_ = new QVBoxLayout(errorFrame_);
  errorFrame_->hide();

  formScroll_ = new QScrollArea;
  formScroll_->setObjectName(QStringLiteral("brushForm"));
  formScroll_->setWidgetResizable(true);
  formScroll_->setFrameShape(QFrame::NoFrame);
  // The form follows the dock's width (combo boxes shrink) instead of scrolling sideways.
  formScroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(brushList_);
  splitter->addWidget(formScroll_);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 2);
  // A third for the list, two for the form, whatever sizes the first layout pass saw.
  splitter->setSizes({1000, 2000});
  splitter->setChildrenCollapsible(false);

  // Stroke options: the same for every brush.
  strokeOptions_ = new StrokeOptionsBox;
  connect(strokeOptions_, &StrokeOptionsBox::changed, this, &BrushPanel::settingsChanged);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(errorFrame_);
  layout->addWidget(splitter, 1);
  layout->addWidget(strokeOptions_);

  rebuildForm();
}

BrushPanel::~BrushPanel() = default;

void BrushPanel::setBrushes(std::vector<gpu::BrushManifest> brushes,
                            std::vector<std::string> errors) {
  brushes_ = std::move(brushes);
  errors_ = std::move(errors);
  store_.setBrushes(brushes_); // a duplicate id: the first one wins, as in findBrush

  fillBrushTree(*brushList_, brushes_);
  const QStringList ids = brushIds();
  if (!ids.contains(currentId_))
    currentId_ = ids.contains(QStringLiteral("push")) ? QStringLiteral("push") : ids.value(0);
  {
    const QSignalBlocker block(brushList_);
    for (QTreeWidgetItemIterator it(brushList_); *it; ++it)
      if ((*it)->data(0, kBrushIdRole).toString() == currentId_ && !currentId_.isEmpty())
        brushList_->setCurrentItem(*it);
  }
  showBrushErrors(*errorFrame_, *errorLayout_, errors_);
  rebuildForm();
  emit settingsChanged();
}

BrushSettings BrushPanel::settings() const {
  const BrushValues& v = currentValues();
  BrushSettings s;
  s.brushId = currentId_.toStdString();
  s.radius = v.radius;
  s.radiusUnit = radiusUnit_;
  s.radiusPixels = v.radiusPixels;
  s.strength = v.strength;
  s.falloff = v.falloff;
  s.area = v.area;
  s.parameters = v.parameters;
  s.pressureTarget = strokeOptions_->pressureTarget();
  s.stabilizer = strokeOptions_->stabilizer();
  s.symmetry = strokeOptions_->symmetry();
  s.keepDetail = strokeOptions_->keepDetail();
  return s;
}

QString BrushPanel::currentBrushId() const {
  return currentId_;
}

const gpu::BrushManifest* BrushPanel::currentBrush() const {
  return findBrush(currentId_);
}

bool BrushPanel::selectBrush(const QString& id) {
  for (QTreeWidgetItemIterator it(brushList_); *it; ++it) {
    if (id.isEmpty() || (*it)->data(0, kBrushIdRole).toString() != id) continue;
    {
      const QSignalBlocker block(brushList_);
      brushList_->setCurrentItem(*it);
    }
    makeCurrent(id);
    return true;
  }
  return false;
}

QStringList BrushPanel::brushIds() const {
  QStringList ids;
  for (QTreeWidgetItemIterator it(brushList_); *it; ++it) {
    const QString id = (*it)->data(0, kBrushIdRole).toString();
    if (!id.isEmpty()) ids.append(id);
  }
  return ids;
}

QStringList BrushPanel::errors() const {
  QStringList out;
  for (const std::string& e : errors_)
    out.append(QString::fromStdString(e));
  return out;
}

void BrushPanel::setRadius(float fractionOfDiagonal) {
  const float r = clampFinite(fractionOfDiagonal, kMinRadius, kMaxRadius, currentValues().radius);
  if (r == currentValues().radius) return;
  currentValues().radius = r;
  if (radiusField_ && radiusUnit_ == RadiusUnit::Scene) radiusField_->setValue(radiusUnit_, r);
  valuesEdited();
}

void BrushPanel::setRadiusPixels(float pixels) {
  const float r =
      clampFinite(pixels, kMinRadiusPixels, kMaxRadiusPixels, currentValues().radiusPixels);
  if (r == currentValues().radiusPixels) return;
  currentValues().radiusPixels = r;
  if (radiusField_ && radiusUnit_ == RadiusUnit::View) radiusField_->setValue(radiusUnit_, r);
  valuesEdited();
}

void BrushPanel::setRadiusUnit(RadiusUnit unit) {
  if (unit == radiusUnit_) return;
  radiusUnit_ = unit;
  BrushValueStore::saveRadiusUnit(unit);
  if (radiusField_) radiusField_->setValue(unit, radiusInUnit());
  emit settingsChanged();
}

void BrushPanel::setRadiusInUnit(float value) {
  radiusUnit_ == RadiusUnit::View ? setRadiusPixels(value) : setRadius(value);
}

float BrushPanel::radiusInUnit() const {
  return radiusUnit_ == RadiusUnit::View ? radiusPixels() : radius();
}

void BrushPanel::setStrength(float s) {
  const float clamped = clampFinite(s, 0.0f, 1.0f, currentValues().strength);
  if (clamped == currentValues().strength) return;
  currentValues().strength = clamped;
  if (strengthSpin_) {
    const QSignalBlocker block(strengthSpin_);
    strengthSpin_->setValue(static_cast<double>(clamped) * 100.0);
  }
  valuesEdited();
}

float BrushPanel::radius() const {
  return currentValues().radius;
}

float BrushPanel::strength() const {
  return currentValues().strength;
}

void BrushPanel::setPressureTarget(PressureTarget target) {
  strokeOptions_->setPressureTarget(target);
}

void BrushPanel::setStabilizer(float amount) {
  strokeOptions_->setStabilizer(amount);
}

void BrushPanel::setSymmetry(unsigned axes) {
  strokeOptions_->setSymmetry(axes);
}

void BrushPanel::setKeepDetail(bool on) {
  strokeOptions_->setKeepDetail(on);
}

QWidget* BrushPanel::parameterWidget(const QString& id) const {
  const auto it = parameterWidgets_.find(id);
  return it != parameterWidgets_.end() ? it->second.data() : nullptr;
}

// ---------------------------------------------------------------------------------------------

const gpu::BrushManifest* BrushPanel::findBrush(const QString& id) const {
  if (id.isEmpty()) return nullptr;
  const std::string key = id.toStdString();
  for (const gpu::BrushManifest& brush : brushes_)
    if (brush.id == key) return &brush;
  return nullptr;
}

BrushValues& BrushPanel::currentValues() {
  BrushValues* values = store_.find(currentId_);
  return values ? *values : noBrush_;
}

const BrushValues& BrushPanel::currentValues() const {
  const BrushValues* values = store_.find(currentId_);
  return values ? *values : noBrush_;
}

void BrushPanel::setMaterials(QStringList ids) {
  if (ids == store_.materials()) return;
  store_.setMaterials(std::move(ids));
  rebuildForm();
}

// ---------------------------------------------------------------------------------------------

void BrushPanel::onCurrentItemChanged(QTreeWidgetItem* item) {
  const QString id = item ? item->data(0, kBrushIdRole).toString() : QString();
  if (!id.isEmpty()) makeCurrent(id);
}

void BrushPanel::makeCurrent(const QString& id) {
  if (id == currentId_) return;
  currentId_ = id;
  rebuildForm();
  emit settingsChanged();
}

void BrushPanel::valuesEdited() {
  if (const gpu::BrushManifest* brush = currentBrush()) store_.save(*brush);
  emit settingsChanged();
}

void BrushPanel::rebuildForm() {
  parameterWidgets_.clear();
  // Only the brush list and the setters call this, never a widget inside the old form, so the
  // form can go at once (deleteLater would leave stale widgets for findChild in the meantime).
  delete formScroll_->takeWidget();

  auto* form = new QWidget;
  auto* layout = new QFormLayout(form);
  layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  formScroll_->setWidget(form);

  const gpu::BrushManifest* brush = currentBrush();
  if (!brush) {
    layout->addRow(new QLabel(tr("No brush loaded.")));
    radiusField_ = nullptr;
    strengthSpin_ = nullptr;
    return;
  }
  const BrushValues& v = currentValues();

  if (!brush->description.empty()) {
    auto* description = new QLabel(QString::fromStdString(brush->description));
    description->setObjectName(QStringLiteral("brushDescription"));
    description->setWordWrap(true);
    layout->addRow(description);
  }

  radiusField_ = new RadiusField;
  radiusField_->setValue(radiusUnit_, radiusInUnit());
  connect(radiusField_, &RadiusField::valueEdited, this, [this](float value) {
    // Within the unit's limits: the field's range.
    (radiusUnit_ == RadiusUnit::View ? currentValues().radiusPixels : currentValues().radius) =
        value;
    valuesEdited();
  });
  connect(radiusField_, &RadiusField::unitChosen, this, &BrushPanel::setRadiusUnit);
  layout->addRow(tr("Radius"), radiusField_);

  strengthSpin_ = new QDoubleSpinBox;
  strengthSpin_->setObjectName(QStringLiteral("strength"));
  strengthSpin_->setDecimals(1);
  strengthSpin_->setRange(0.0, 100.0);
  strengthSpin_->setSingleStep(5.0);
  strengthSpin_->setSuffix(QStringLiteral(" %"));
  strengthSpin_->setValue(static_cast<double>(v.strength) * 100.0);
  strengthSpin_->setToolTip(tr("How strongly one dab acts, in percent (of the radius for "
                               "brushes that move the surface)"));
  connect(strengthSpin_, &QDoubleSpinBox::valueChanged, this, [this](double percent) {
    currentValues().strength = std::clamp(static_cast<float>(percent / 100.0), 0.0f, 1.0f);
    valuesEdited();
  });
  layout->addRow(tr("Strength"), strengthSpin_);

  auto* falloff = makeNarrowCombo();
  falloff->setObjectName(QStringLiteral("falloff"));
  for (const gpu::Falloff f :
       {gpu::Falloff::Linear, gpu::Falloff::Smooth, gpu::Falloff::Constant, gpu::Falloff::Curve}) {
    if (f == gpu::Falloff::Curve && brush->falloffCurve.empty()) continue;
    falloff->addItem(falloffTitle(f), static_cast<int>(f));
  }
  falloff->setCurrentIndex(falloff->findData(static_cast<int>(v.falloff)));
  falloff->setToolTip(tr("How the effect fades from the centre to the rim"));
  connect(falloff, &QComboBox::currentIndexChanged, this, [this, falloff](int index) {
    if (index < 0) return;
    currentValues().falloff = static_cast<gpu::Falloff>(falloff->itemData(index).toInt());
    valuesEdited();
  });
  layout->addRow(tr("Falloff"), falloff);

  auto* area = makeNarrowCombo();
  area->setObjectName(QStringLiteral("area"));
  for (const gpu::AreaMode a :
       {gpu::AreaMode::Uv, gpu::AreaMode::Volume, gpu::AreaMode::VolumeNormal})
    area->addItem(areaTitle(a), static_cast<int>(a));
  area->setCurrentIndex(area->findData(static_cast<int>(v.area)));
  area->setToolTip(tr("Where a dab applies: a disc in texture space, a sphere around the "
                      "centre, or that sphere limited to surface facing the same way"));
  connect(area, &QComboBox::currentIndexChanged, this, [this, area](int index) {
    if (index < 0) return;
    currentValues().area = static_cast<gpu::AreaMode>(area->itemData(index).toInt());
    valuesEdited();
  });
  layout->addRow(tr("Area"), area);

  parameterWidgets_ = addParameterRows(*layout, *brush, v.parameters, store_.materials(),
                                       [this](const std::string& id, std::array<float, 4> value) {
                                         currentValues().parameters[id] =
                                             value; // the form is rebuilt when the brush changes
                                         valuesEdited();
                                       });
}

} // namespace octaclay::app
