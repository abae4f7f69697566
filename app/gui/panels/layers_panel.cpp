// The Layers dock panel. The panel owns visibility and target; the widgets mirror them, so a
// setter and a click take the same path (store, persist, update the widget, signal).

#include "layers_panel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QRadioButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace octaclay::app {

namespace {

using core::EditLayer;

constexpr std::array kLayers{core::EditLayer::Positions, core::EditLayer::Diffuse,
                             core::EditLayer::Feature, core::EditLayer::Mask};

std::size_t indexOf(core::EditLayer layer) {
  return static_cast<std::size_t>(layer);
}

QString layerKey(core::EditLayer layer) {
  const std::string_view name = gpu::toManifestName(layer);
  return QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
}

QString layerTitle(core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Positions:
    return LayersPanel::tr("Positions");
  case core::EditLayer::Diffuse:
    return LayersPanel::tr("Diffuse");
  case core::EditLayer::Feature:
    return LayersPanel::tr("Feature");
  case core::EditLayer::Mask:
    return LayersPanel::tr("Mask");
  }
  return {};
}

QString visibilityTip(core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Positions:
    return LayersPanel::tr("The surface itself is always shown");
  case core::EditLayer::Diffuse:
    return LayersPanel::tr("Show the painted colour (off: plain clay)");
  case core::EditLayer::Feature:
    return LayersPanel::tr("Show the feature layer's height, specular and reflectivity");
  case core::EditLayer::Mask:
    return LayersPanel::tr("Tint masked (protected) areas");
  }
  return {};
}

QString stateText(bool painted) {
  return painted ? LayersPanel::tr("painted") : LayersPanel::tr("uniform");
}

} // namespace

LayersPanel::LayersPanel(QWidget* parent) : QWidget(parent) {
  painted_[indexOf(core::EditLayer::Positions)] = true; // the surface is always real data

  QSettings settings;
  settings.beginGroup(QStringLiteral("layers"));
  for (const core::EditLayer layer : kLayers)
    if (layer != core::EditLayer::Positions)
      visible_[indexOf(layer)] =
          settings.value(QStringLiteral("visible/") + layerKey(layer), true).toBool();
  const QString target = settings.value(QStringLiteral("paintTarget")).toString();
  for (const core::EditLayer layer : kLayers)
    if (layer != core::EditLayer::Positions && target == layerKey(layer)) paintTarget_ = layer;

  auto* grid = new QGridLayout;
  grid->addWidget(new QLabel(tr("<b>Layer</b>")), 0, 0);
  grid->addWidget(new QLabel(tr("<b>Show</b>")), 0, 1);
  grid->addWidget(new QLabel(tr("<b>Paint</b>")), 0, 2);
  grid->addWidget(new QLabel(tr("<b>State</b>")), 0, 3);

  targetGroup_ = new QButtonGroup(this);
  targetGroup_->setExclusive(true);
  for (const core::EditLayer layer : kLayers) {
    const std::size_t k = indexOf(layer);
    const int row = static_cast<int>(k) + 1;
    grid->addWidget(new QLabel(layerTitle(layer)), row, 0);

    auto* box = new QCheckBox;
    box->setObjectName(QStringLiteral("visible-") + layerKey(layer));
    box->setToolTip(visibilityTip(layer));
    box->setChecked(visible_[k]);
    if (layer == core::EditLayer::Positions) {
      box->setEnabled(false);
    } else {
      connect(box, &QCheckBox::toggled, this, [this, layer](bool on) { setVisible(layer, on); });
    }
    visibleBoxes_[k] = box;
    grid->addWidget(box, row, 1);

    if (layer != core::EditLayer::Positions) {
      auto* radio = new QRadioButton;
      radio->setObjectName(QStringLiteral("target-") + layerKey(layer));
      radio->setToolTip(tr("Paint brushes write the %1 layer").arg(layerTitle(layer)));
      radio->setChecked(layer == paintTarget_);
      targetGroup_->addButton(radio);
      connect(radio, &QRadioButton::toggled, this, [this, layer](bool on) {
        if (on) setPaintTarget(layer);
      });
      targetButtons_[k] = radio;
      grid->addWidget(radio, row, 2);
    }

    auto* state = new QLabel(stateText(painted_[k]));
    state->setObjectName(QStringLiteral("state-") + layerKey(layer));
    state->setToolTip(tr("Painted: the layer holds per-sample data. Uniform: it is still one "
                         "value everywhere and costs no memory."));
    stateLabels_[k] = state;
    grid->addWidget(state, row, 3);
  }
  grid->setColumnStretch(3, 1);

  // One channel alone, to see what a paint or splat stroke wrote where.
  preview_ = new QComboBox(this);
  preview_->setObjectName(QStringLiteral("preview"));
  preview_->addItems({tr("Shaded model"), tr("Diffuse colour"), tr("Height detail"), tr("Specular"),
                      tr("Reflectivity"), tr("Mask"), tr("Saliency"), tr("Stretch")});
  preview_->setToolTip(
      tr("Show the shaded model, one layer channel alone, the saliency the level of detail "
         "keeps (a heat map: blue smooth, red salient), or the stretch: how far apart the "
         "samples lie against the model's mean sample spacing, on a log scale in the same "
         "colours: blue 2× or less (a fresh sphere lies between 0.6× and 1.7×), green 2.8×, "
         "red 4× or more, where too few samples are left to keep detail"));
  connect(preview_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) emit previewChanged(static_cast<Preview>(index)); // rows in Preview's order
  });
  auto* previewRow = new QHBoxLayout;
  previewRow->addWidget(new QLabel(tr("Preview"), this));
  previewRow->addWidget(preview_, 1);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(grid);
  layout->addLayout(previewRow);
  layout->addStretch(1);
}

LayersPanel::Preview LayersPanel::preview() const {
  return static_cast<Preview>(std::max(preview_->currentIndex(), 0));
}
void LayersPanel::setPreview(Preview preview) {
  preview_->setCurrentIndex(static_cast<int>(preview));
}
void LayersPanel::setPreview(int row) {
  preview_->setCurrentIndex(row);
}

bool LayersPanel::isVisible(core::EditLayer layer) const {
  return layer == core::EditLayer::Positions || visible_[indexOf(layer)];
}

void LayersPanel::setVisible(core::EditLayer layer, bool visible) {
  const std::size_t k = indexOf(layer);
  if (layer == core::EditLayer::Positions || visible_[k] == visible) return;
  visible_[k] = visible;
  {
    const QSignalBlocker block(visibleBoxes_[k]);
    visibleBoxes_[k]->setChecked(visible);
  }
  save();
  emit visibilityChanged();
}

core::EditLayer LayersPanel::paintTarget() const {
  return paintTarget_;
}

void LayersPanel::setPaintTarget(core::EditLayer layer) {
  if (layer == core::EditLayer::Positions || layer == paintTarget_) return;
  paintTarget_ = layer;
  {
    QRadioButton* button = targetButtons_[indexOf(layer)];
    const QSignalBlocker block(button); // its toggled() would come back here
    button->setChecked(true);
  }
  save();
  emit paintTargetChanged();
}

void LayersPanel::setLayerState(core::EditLayer layer, bool painted) {
  const std::size_t k = indexOf(layer);
  painted_[k] = painted;
  stateLabels_[k]->setText(stateText(painted));
}

bool LayersPanel::isPainted(core::EditLayer layer) const {
  return painted_[indexOf(layer)];
}

QString LayersPanel::layerStateText(core::EditLayer layer) const {
  return stateLabels_[indexOf(layer)]->text();
}

void LayersPanel::save() const {
  QSettings settings;
  settings.beginGroup(QStringLiteral("layers"));
  for (const core::EditLayer layer : kLayers)
    if (layer != core::EditLayer::Positions)
      settings.setValue(QStringLiteral("visible/") + layerKey(layer), visible_[indexOf(layer)]);
  settings.setValue(QStringLiteral("paintTarget"), layerKey(paintTarget_));
}

} // namespace octaclay::app
