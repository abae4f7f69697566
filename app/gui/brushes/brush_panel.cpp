// The Brushes dock panel: a view of BrushState. The state owns the brushes' values; widgets only
// show and edit them, so a value never depends on a widget's rounding (a spin box with one
// decimal still shows, not changes, the exact radius given to BrushState::setRadius).

#include "brush_panel.h"

#include "brush_list.h"
#include "brush_state.h"
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

BrushPanel::BrushPanel(BrushState& state, QWidget* parent) : QWidget(parent), state_(state) {
  brushList_ = new QTreeWidget;
  brushList_->setObjectName(QStringLiteral("brushList"));
  brushList_->setHeaderHidden(true);
  brushList_->setRootIsDecorated(false);
  brushList_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(brushList_, &QTreeWidget::itemSelectionChanged, this, [this] {
    const QList<QTreeWidgetItem*> selected = brushList_->selectedItems();
    if (!selected.isEmpty()) state_.selectBrush(selected.front()->data(0, kBrushIdRole).toString());
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

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(errorFrame_);
  layout->addWidget(splitter, 1);
  layout->addWidget(new StrokeOptionsBox(state_)); // the same for every brush

  connect(&state_, &BrushState::brushesChanged, this, &BrushPanel::showBrushes);
  connect(&state_, &BrushState::brushSelected, this, &BrushPanel::showCurrentBrush);
  connect(&state_, &BrushState::changed, this, &BrushPanel::showValues);
  showBrushes();
}

BrushPanel::~BrushPanel() = default;

QWidget* BrushPanel::parameterWidget(const QString& id) const {
  const auto it = parameterWidgets_.find(id);
  return it != parameterWidgets_.end() ? it->second.data() : nullptr;
}

void BrushPanel::showBrushes() {
  fillBrushTree(*brushList_, state_.brushes());
  showBrushErrors(*errorFrame_, *errorLayout_, state_.errorTexts());
  showCurrentBrush();
}

void BrushPanel::showCurrentBrush() {
  {
    const QSignalBlocker block(brushList_);
    const QString current = state_.currentBrushId();
    for (QTreeWidgetItemIterator it(brushList_); *it; ++it)
      if (!current.isEmpty() && (*it)->data(0, kBrushIdRole).toString() == current)
        brushList_->setCurrentItem(*it);
  }
  rebuildForm();
}

// The form shows what the state holds; widgets are updated without echoing their edits back.
void BrushPanel::showValues() {
  if (radiusField_) radiusField_->setValue(state_.radiusUnit(), state_.radiusInUnit());
  if (strengthSpin_) {
    const QSignalBlocker block(strengthSpin_);
    strengthSpin_->setValue(static_cast<double>(state_.strength()) * 100.0);
  }
  const auto show = [](QComboBox* combo, int value) {
    const QSignalBlocker block(combo);
    combo->setCurrentIndex(combo->findData(value));
  };
  if (falloffCombo_) show(falloffCombo_, static_cast<int>(state_.values().falloff));
  if (areaCombo_) show(areaCombo_, static_cast<int>(state_.values().area));
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

  const gpu::BrushManifest* brush = state_.currentBrush();
  if (!brush) {
    layout->addRow(new QLabel(tr("No brush loaded.")));
    return;
  }
  const BrushValues& v = state_.values();

  if (!brush->description.empty()) {
    auto* description = new QLabel(QString::fromStdString(brush->description));
    description->setObjectName(QStringLiteral("brushDescription"));
    description->setWordWrap(true);
    layout->addRow(description);
  }

  radiusField_ = new RadiusField;
  radiusField_->setValue(state_.radiusUnit(), state_.radiusInUnit());
  connect(radiusField_, &RadiusField::valueEdited, &state_, &BrushState::setRadiusInUnit);
  connect(radiusField_, &RadiusField::unitChosen, &state_, &BrushState::setRadiusUnit);
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
  connect(strengthSpin_, &QDoubleSpinBox::valueChanged, this,
          [this](double percent) { state_.setStrength(static_cast<float>(percent / 100.0)); });
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
    state_.setFalloff(static_cast<gpu::Falloff>(falloff->itemData(index).toInt()));
  });
  layout->addRow(tr("Falloff"), falloff);
  falloffCombo_ = falloff;

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
    state_.setArea(static_cast<gpu::AreaMode>(area->itemData(index).toInt()));
  });
  layout->addRow(tr("Area"), area);
  areaCombo_ = area;

  parameterWidgets_ = addParameterRows(*layout, *brush, v.parameters, state_.materials(),
                                       [this](const std::string& id, std::array<float, 4> value) {
                                         state_.setParameter(id, value);
                                       });
}

} // namespace octaclay::app
