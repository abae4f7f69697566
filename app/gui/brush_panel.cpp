// The Brushes dock panel. The panel owns the values (values_, the stroke options); widgets only
// show and edit them, so setters never depend on a widget's rounding (a spin box with one
// decimal still hands back the exact radius given to setRadius).

#include "brush_panel.h"

#include "octaclay/gpu/stroke.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFrame>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace octaclay::app {

namespace {

constexpr float kMinRadius = 0.001f, kMaxRadius = 1.0f;
constexpr int kIdRole = Qt::UserRole;
constexpr std::array kCategories{gpu::Category::Sculpt, gpu::Category::Paint, gpu::Category::Splat};
constexpr std::array kAxes{gpu::kSymmetryX, gpu::kSymmetryY, gpu::kSymmetryZ};

QString toQString(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString categoryTitle(gpu::Category category) {
  switch (category) {
  case gpu::Category::Sculpt:
    return BrushPanel::tr("Sculpt");
  case gpu::Category::Paint:
    return BrushPanel::tr("Paint");
  case gpu::Category::Splat:
    return BrushPanel::tr("Splat");
  }
  return {};
}

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

constexpr std::array kPressureNames{"none", "radius", "strength"};

// The enum value whose manifest name is `name`, if any.
template <typename Enum, std::size_t N> std::optional<Enum> fromManifestName(const QString& name) {
  for (std::size_t k = 0; k < N; ++k) {
    const auto value = static_cast<Enum>(k);
    if (name == toQString(gpu::toManifestName(value))) return value;
  }
  return std::nullopt;
}

// Decimals that show step, min, max and the default exactly (up to 6): 0.25 → 2, 0.1 → 1.
int decimalsFor(const gpu::BrushParameter& parameter) {
  int decimals = 0;
  for (const float v : {parameter.step, parameter.min, parameter.max, parameter.defaultValue[0]}) {
    int d = 0;
    double scaled = std::abs(static_cast<double>(v));
    while (d < 6 && std::abs(scaled - std::round(scaled)) > 1e-6 * std::max(1.0, scaled)) {
      scaled *= 10.0;
      ++d;
    }
    decimals = std::max(decimals, d);
  }
  return decimals;
}

float clampFinite(float value, float lo, float hi, float fallback) {
  return std::isfinite(value) ? std::clamp(value, lo, hi) : fallback;
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

QColor toColor(const std::array<float, 4>& v) {
  return QColor::fromRgbF(v[0], v[1], v[2], v[3]);
}

// Error text with zero-width spaces after path separators, so a long path wraps in the label
// instead of widening the dock.
QString wrappable(const QString& text) {
  QString out;
  out.reserve(text.size() + text.size() / 8);
  for (const QChar c : text) {
    out += c;
    if (c == u'/' || c == u'\\') out += QChar(0x200B);
  }
  return out;
}

// A combo box that can be narrower than its longest item, so a narrow dock stays usable.
QComboBox* makeCombo() {
  auto* combo = new QComboBox;
  combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo->setMinimumContentsLength(8);
  return combo;
}

QString settingsGroup(const QString& id) {
  return QStringLiteral("brushes/") + id;
}

} // namespace

// ---------------------------------------------------------------------------------------------

ColorButton::ColorButton(QWidget* parent) : QPushButton(parent) {
  connect(this, &QPushButton::clicked, this, &ColorButton::pickColor);
  setColor(Qt::white);
}

void ColorButton::setColor(const QColor& color) {
  const bool changed = color != color_;
  color_ = color;
  QPixmap swatch(16, 16);
  swatch.fill(color);
  setIcon(QIcon(swatch));
  setText(color.name(color.alpha() < 255 ? QColor::HexArgb : QColor::HexRgb));
  if (changed) emit colorChanged(color_);
}

void ColorButton::pickColor() {
  const QColor picked =
      QColorDialog::getColor(color_, this, tr("Choose a colour"), QColorDialog::ShowAlphaChannel);
  if (picked.isValid()) setColor(picked);
}

// ---------------------------------------------------------------------------------------------

BrushPanel::BrushPanel(QWidget* parent) : QWidget(parent) {
  loadStrokeOptions();

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
  splitter->setChildrenCollapsible(false);

  // Stroke options: the same for every brush.
  auto* stroke = new QGroupBox(tr("Stroke"));
  auto* strokeLayout = new QFormLayout(stroke);

  pressureCombo_ = makeCombo();
  pressureCombo_->setObjectName(QStringLiteral("pressureTarget"));
  pressureCombo_->addItem(tr("None"), static_cast<int>(PressureTarget::None));
  pressureCombo_->addItem(tr("Radius"), static_cast<int>(PressureTarget::Radius));
  pressureCombo_->addItem(tr("Strength"), static_cast<int>(PressureTarget::Strength));
  pressureCombo_->setCurrentIndex(static_cast<int>(pressureTarget_));
  pressureCombo_->setToolTip(tr("What pen pressure scales"));
  connect(pressureCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) setPressureTarget(static_cast<PressureTarget>(index));
  });
  strokeLayout->addRow(tr("Pressure"), pressureCombo_);

  stabilizerSlider_ = new QSlider(Qt::Horizontal);
  stabilizerSlider_->setObjectName(QStringLiteral("stabilizer"));
  stabilizerSlider_->setRange(0, 100);
  stabilizerSlider_->setValue(stabilizerPercent_);
  stabilizerSlider_->setToolTip(tr("Lazy mouse: how far the brush trails the cursor, smoothing "
                                   "the stroke (0 follows the cursor exactly)"));
  stabilizerLabel_ = new QLabel;
  stabilizerLabel_->setMinimumWidth(
      stabilizerLabel_->fontMetrics().horizontalAdvance(QStringLiteral("100 %")));
  stabilizerLabel_->setText(QStringLiteral("%1 %").arg(stabilizerPercent_));
  connect(stabilizerSlider_, &QSlider::valueChanged, this,
          [this](int percent) { setStabilizer(static_cast<float>(percent) / 100.0f); });
  auto* stabilizerRow = new QHBoxLayout;
  stabilizerRow->addWidget(stabilizerSlider_, 1);
  stabilizerRow->addWidget(stabilizerLabel_);
  strokeLayout->addRow(tr("Stabilizer"), stabilizerRow);

  auto* symmetryRow = new QHBoxLayout;
  const std::array<QString, 3> axisNames{QStringLiteral("X"), QStringLiteral("Y"),
                                         QStringLiteral("Z")};
  for (std::size_t k = 0; k < 3; ++k) {
    auto* box = new QCheckBox(axisNames[k]);
    box->setObjectName(QStringLiteral("symmetry") + axisNames[k]);
    box->setToolTip(tr("Mirror strokes across the model's %1 = 0 plane").arg(axisNames[k]));
    box->setChecked((symmetry_ & kAxes[k]) != 0);
    const unsigned bit = kAxes[k];
    connect(box, &QCheckBox::toggled, this,
            [this, bit](bool on) { setSymmetry(on ? symmetry_ | bit : symmetry_ & ~bit); });
    symmetryBoxes_[k] = box;
    symmetryRow->addWidget(box);
  }
  symmetryRow->addStretch(1);
  strokeLayout->addRow(tr("Symmetry"), symmetryRow);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(errorFrame_);
  layout->addWidget(splitter, 1);
  layout->addWidget(stroke);

  rebuildForm();
}

BrushPanel::~BrushPanel() = default;

void BrushPanel::setBrushes(std::vector<gpu::BrushManifest> brushes,
                            std::vector<std::string> errors) {
  brushes_ = std::move(brushes);
  errors_ = std::move(errors);

  std::map<QString, BrushValues> values;
  for (const gpu::BrushManifest& brush : brushes_) {
    const QString id = QString::fromStdString(brush.id);
    if (values.count(id) != 0) continue; // a duplicate id: the first one wins, as in findBrush
    const auto known = values_.find(id);
    BrushValues v = known != values_.end() ? known->second : loadValues(brush);
    fitValues(brush, v);
    values.emplace(id, std::move(v));
  }
  values_ = std::move(values);

  fillBrushList();
  const QStringList ids = brushIds();
  if (!ids.contains(currentId_))
    currentId_ = ids.contains(QStringLiteral("push")) ? QStringLiteral("push") : ids.value(0);
  {
    const QSignalBlocker block(brushList_);
    for (QTreeWidgetItemIterator it(brushList_); *it; ++it)
      if ((*it)->data(0, kIdRole).toString() == currentId_ && !currentId_.isEmpty())
        brushList_->setCurrentItem(*it);
  }
  showErrors();
  rebuildForm();
  emit settingsChanged();
}

BrushSettings BrushPanel::settings() const {
  const BrushValues& v = currentValues();
  BrushSettings s;
  s.brushId = currentId_.toStdString();
  s.radius = v.radius;
  s.strength = v.strength;
  s.falloff = v.falloff;
  s.area = v.area;
  s.parameters = v.parameters;
  s.pressureTarget = pressureTarget_;
  s.stabilizer = static_cast<float>(stabilizerPercent_) / 100.0f;
  s.symmetry = symmetry_;
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
    if (id.isEmpty() || (*it)->data(0, kIdRole).toString() != id) continue;
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
    const QString id = (*it)->data(0, kIdRole).toString();
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
  if (radiusSpin_) {
    const QSignalBlocker block(radiusSpin_);
    radiusSpin_->setValue(static_cast<double>(r) * 100.0);
  }
  valuesEdited();
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
  if (target == pressureTarget_) return;
  pressureTarget_ = target;
  {
    const QSignalBlocker block(pressureCombo_);
    pressureCombo_->setCurrentIndex(static_cast<int>(target));
  }
  saveStrokeOptions();
  emit settingsChanged();
}

void BrushPanel::setStabilizer(float amount) {
  const int percent = static_cast<int>(std::lround(clampFinite(amount, 0.0f, 1.0f, 0.0f) * 100.0f));
  if (percent == stabilizerPercent_) return;
  stabilizerPercent_ = percent;
  {
    const QSignalBlocker block(stabilizerSlider_);
    stabilizerSlider_->setValue(percent);
  }
  stabilizerLabel_->setText(QStringLiteral("%1 %").arg(percent));
  saveStrokeOptions();
  emit settingsChanged();
}

void BrushPanel::setSymmetry(unsigned axes) {
  axes &= gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ;
  if (axes == symmetry_) return;
  symmetry_ = axes;
  for (std::size_t k = 0; k < 3; ++k) {
    const QSignalBlocker block(symmetryBoxes_[k]);
    symmetryBoxes_[k]->setChecked((axes & kAxes[k]) != 0);
  }
  saveStrokeOptions();
  emit settingsChanged();
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

BrushPanel::BrushValues& BrushPanel::currentValues() {
  const auto it = values_.find(currentId_);
  return it != values_.end() ? it->second : noBrush_;
}

const BrushPanel::BrushValues& BrushPanel::currentValues() const {
  const auto it = values_.find(currentId_);
  return it != values_.end() ? it->second : noBrush_;
}

void BrushPanel::setMaterials(QStringList ids) {
  if (ids == materials_) return;
  materials_ = std::move(ids);
  rebuildForm();
}

BrushPanel::BrushValues BrushPanel::defaultValues(const gpu::BrushManifest& brush) const {
  BrushValues v;
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

BrushPanel::BrushValues BrushPanel::loadValues(const gpu::BrushManifest& brush) const {
  BrushValues v = defaultValues(brush);
  QSettings settings;
  settings.beginGroup(settingsGroup(QString::fromStdString(brush.id)));
  bool ok = false;
  if (const float r = settings.value(QStringLiteral("radius")).toFloat(&ok); ok) v.radius = r;
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

void BrushPanel::fitValues(const gpu::BrushManifest& brush, BrushValues& values) const {
  values.radius = clampFinite(values.radius, kMinRadius, kMaxRadius, BrushValues{}.radius);
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

void BrushPanel::saveValues(const QString& id) const {
  const gpu::BrushManifest* brush = findBrush(id);
  const auto it = values_.find(id);
  if (!brush || it == values_.end()) return;
  const BrushValues& v = it->second;
  QSettings settings;
  settings.beginGroup(settingsGroup(id));
  settings.setValue(QStringLiteral("radius"), static_cast<double>(v.radius));
  settings.setValue(QStringLiteral("strength"), static_cast<double>(v.strength));
  settings.setValue(QStringLiteral("falloff"), toQString(gpu::toManifestName(v.falloff)));
  settings.setValue(QStringLiteral("area"), toQString(gpu::toManifestName(v.area)));
  settings.beginGroup(QStringLiteral("parameters"));
  for (const gpu::BrushParameter& p : brush->parameters) {
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

void BrushPanel::saveStrokeOptions() const {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  settings.setValue(QStringLiteral("pressureTarget"),
                    QString::fromLatin1(kPressureNames[static_cast<std::size_t>(pressureTarget_)]));
  settings.setValue(QStringLiteral("stabilizer"), stabilizerPercent_);
  settings.setValue(QStringLiteral("symmetry"), symmetry_);
}

void BrushPanel::loadStrokeOptions() {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  const QString pressure = settings.value(QStringLiteral("pressureTarget")).toString();
  for (std::size_t k = 0; k < kPressureNames.size(); ++k)
    if (pressure == QLatin1String(kPressureNames[k]))
      pressureTarget_ = static_cast<PressureTarget>(k);
  bool ok = false;
  if (const int percent = settings.value(QStringLiteral("stabilizer")).toInt(&ok); ok)
    stabilizerPercent_ = std::clamp(percent, 0, 100);
  if (const uint axes = settings.value(QStringLiteral("symmetry")).toUInt(&ok); ok)
    symmetry_ = axes & (gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ);
}

// ---------------------------------------------------------------------------------------------

void BrushPanel::fillBrushList() {
  const QSignalBlocker block(brushList_);
  brushList_->clear();
  for (const gpu::Category category : kCategories) {
    QTreeWidgetItem* header = nullptr;
    for (const gpu::BrushManifest& brush : brushes_) {
      if (brush.category != category) continue;
      if (!header) {
        header = new QTreeWidgetItem(brushList_, {categoryTitle(category)});
        header->setFlags(Qt::ItemIsEnabled);
        QFont font = header->font(0);
        font.setBold(true);
        header->setFont(0, font);
      }
      auto* item = new QTreeWidgetItem(header, {QString::fromStdString(brush.name)});
      item->setData(0, kIdRole, QString::fromStdString(brush.id));
      item->setToolTip(0,
                       QStringLiteral("%1\n%2").arg(QString::fromStdString(brush.description),
                                                    QString::fromStdString(brush.folder.string())));
    }
  }
  brushList_->expandAll();
}

void BrushPanel::showErrors() {
  while (QLayoutItem* item = errorLayout_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  errorFrame_->setVisible(!errors_.empty());
  if (errors_.empty()) return;
  // No translator is installed, so spell the plural out rather than rely on tr()'s %n forms.
  auto* heading =
      new QLabel(errors_.size() == 1 ? tr("1 brush could not be loaded:")
                                     : tr("%1 brushes could not be loaded:").arg(errors_.size()));
  QFont bold = heading->font();
  bold.setBold(true);
  heading->setFont(bold);
  errorLayout_->addWidget(heading);
  for (const std::string& error : errors_) {
    const QString text = QString::fromStdString(error);
    auto* label = new QLabel(wrappable(text));
    label->setObjectName(QStringLiteral("brushError"));
    label->setProperty("error", text);
    label->setTextFormat(Qt::PlainText);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    errorLayout_->addWidget(label);
  }
}

void BrushPanel::onCurrentItemChanged(QTreeWidgetItem* item) {
  const QString id = item ? item->data(0, kIdRole).toString() : QString();
  if (!id.isEmpty()) makeCurrent(id);
}

void BrushPanel::makeCurrent(const QString& id) {
  if (id == currentId_) return;
  currentId_ = id;
  rebuildForm();
  emit settingsChanged();
}

void BrushPanel::valuesEdited() {
  saveValues(currentId_);
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
    radiusSpin_ = nullptr;
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

  radiusSpin_ = new QDoubleSpinBox;
  radiusSpin_->setObjectName(QStringLiteral("radius"));
  radiusSpin_->setDecimals(1);
  radiusSpin_->setRange(static_cast<double>(kMinRadius) * 100.0,
                        static_cast<double>(kMaxRadius) * 100.0);
  radiusSpin_->setSingleStep(0.5);
  radiusSpin_->setSuffix(QStringLiteral(" %"));
  radiusSpin_->setValue(static_cast<double>(v.radius) * 100.0);
  radiusSpin_->setToolTip(tr("Brush radius, in percent of the model's bounding-box diagonal"));
  connect(radiusSpin_, &QDoubleSpinBox::valueChanged, this, [this](double percent) {
    currentValues().radius =
        std::clamp(static_cast<float>(percent / 100.0), kMinRadius, kMaxRadius);
    valuesEdited();
  });
  layout->addRow(tr("Radius"), radiusSpin_);

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

  auto* falloff = makeCombo();
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

  auto* area = makeCombo();
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

  for (const gpu::BrushParameter& p : brush->parameters) {
    const auto value = v.parameters.find(p.id);
    QWidget* widget =
        makeParameterWidget(p, value != v.parameters.end() ? value->second : p.defaultValue);
    const QString tooltip = QString::fromStdString(p.tooltip);
    widget->setToolTip(tooltip);
    auto* label = new QLabel(QString::fromStdString(p.label));
    label->setToolTip(tooltip);
    label->setBuddy(widget);
    layout->addRow(label, widget);
    parameterWidgets_[QString::fromStdString(p.id)] = widget;
  }
}

QWidget* BrushPanel::makeParameterWidget(const gpu::BrushParameter& parameter,
                                         const std::array<float, 4>& value) {
  const std::string id = parameter.id;
  // Writes one parameter of the current brush (the form is rebuilt when the brush changes).
  const auto store = [this, id](std::array<float, 4> x) {
    currentValues().parameters[id] = x;
    valuesEdited();
  };
  QWidget* widget = nullptr;
  switch (parameter.type) {
  case gpu::ParameterType::Float: {
    auto* spin = new QDoubleSpinBox;
    spin->setDecimals(decimalsFor(parameter));
    spin->setRange(static_cast<double>(parameter.min), static_cast<double>(parameter.max));
    spin->setSingleStep(static_cast<double>(parameter.step));
    spin->setValue(static_cast<double>(value[0]));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [store](double x) {
      store({static_cast<float>(x), 0.0f, 0.0f, 0.0f});
    });
    widget = spin;
    break;
  }
  case gpu::ParameterType::Int: {
    auto* spin = new QSpinBox;
    spin->setRange(static_cast<int>(std::lround(parameter.min)),
                   static_cast<int>(std::lround(parameter.max)));
    spin->setSingleStep(std::max(1, static_cast<int>(std::lround(parameter.step))));
    spin->setValue(static_cast<int>(std::lround(value[0])));
    connect(spin, &QSpinBox::valueChanged, this, [store](int x) {
      store({static_cast<float>(x), 0.0f, 0.0f, 0.0f});
    });
    widget = spin;
    break;
  }
  case gpu::ParameterType::Bool: {
    auto* box = new QCheckBox;
    box->setChecked(value[0] != 0.0f);
    connect(box, &QCheckBox::toggled, this, [store](bool on) {
      store({on ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f});
    });
    widget = box;
    break;
  }
  case gpu::ParameterType::Color: {
    auto* button = new ColorButton;
    button->setColor(toColor(value));
    connect(button, &ColorButton::colorChanged, this, [store](const QColor& c) {
      store({c.redF(), c.greenF(), c.blueF(), c.alphaF()});
    });
    widget = button;
    break;
  }
  case gpu::ParameterType::Enum: {
    auto* combo = makeCombo();
    for (const std::string& option : parameter.options)
      combo->addItem(QString::fromStdString(option));
    combo->setCurrentIndex(static_cast<int>(std::lround(value[0])));
    connect(combo, &QComboBox::currentIndexChanged, this, [store](int index) {
      if (index >= 0) store({static_cast<float>(index), 0.0f, 0.0f, 0.0f});
    });
    widget = combo;
    break;
  }
  case gpu::ParameterType::Material: {
    auto* combo = makeCombo();
    combo->addItems(materials_);
    combo->setCurrentIndex(static_cast<int>(std::lround(value[0])));
    connect(combo, &QComboBox::currentIndexChanged, this, [store](int index) {
      if (index >= 0) store({static_cast<float>(index), 0.0f, 0.0f, 0.0f});
    });
    widget = combo;
    break;
  }
  }
  widget->setObjectName(QStringLiteral("parameter-") + QString::fromStdString(id));
  return widget;
}

} // namespace octaclay::app
