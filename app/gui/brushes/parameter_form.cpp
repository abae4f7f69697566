#include "parameter_form.h"

#include "color_button.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

#include <algorithm>
#include <cmath>

namespace octaclay::app {
namespace {

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

QColor toColor(const std::array<float, 4>& v) {
  return QColor::fromRgbF(v[0], v[1], v[2], v[3]);
}

QWidget* makeParameterWidget(const gpu::BrushParameter& parameter,
                             const std::array<float, 4>& value, const QStringList& materials,
                             const ParameterEdited& edited) {
  const std::string id = parameter.id;
  const auto store = [edited, id](std::array<float, 4> x) { edited(id, x); };
  QWidget* widget = nullptr;
  switch (parameter.type) {
  case gpu::ParameterType::Float: {
    auto* spin = new QDoubleSpinBox;
    spin->setDecimals(decimalsFor(parameter));
    spin->setRange(static_cast<double>(parameter.min), static_cast<double>(parameter.max));
    spin->setSingleStep(static_cast<double>(parameter.step));
    spin->setValue(static_cast<double>(value[0]));
    QObject::connect(spin, &QDoubleSpinBox::valueChanged, spin, [store](double x) {
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
    QObject::connect(spin, &QSpinBox::valueChanged, spin, [store](int x) {
      store({static_cast<float>(x), 0.0f, 0.0f, 0.0f});
    });
    widget = spin;
    break;
  }
  case gpu::ParameterType::Bool: {
    auto* box = new QCheckBox;
    box->setChecked(value[0] != 0.0f);
    QObject::connect(box, &QCheckBox::toggled, box, [store](bool on) {
      store({on ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f});
    });
    widget = box;
    break;
  }
  case gpu::ParameterType::Color: {
    auto* button = new ColorButton;
    button->setColor(toColor(value));
    QObject::connect(button, &ColorButton::colorChanged, button, [store](const QColor& c) {
      store({c.redF(), c.greenF(), c.blueF(), c.alphaF()});
    });
    widget = button;
    break;
  }
  case gpu::ParameterType::Enum: {
    auto* combo = makeNarrowCombo();
    for (const std::string& option : parameter.options)
      combo->addItem(QString::fromStdString(option));
    combo->setCurrentIndex(static_cast<int>(std::lround(value[0])));
    QObject::connect(combo, &QComboBox::currentIndexChanged, combo, [store](int index) {
      if (index >= 0) store({static_cast<float>(index), 0.0f, 0.0f, 0.0f});
    });
    widget = combo;
    break;
  }
  case gpu::ParameterType::Material: {
    auto* combo = makeNarrowCombo();
    combo->addItems(materials);
    combo->setCurrentIndex(static_cast<int>(std::lround(value[0])));
    QObject::connect(combo, &QComboBox::currentIndexChanged, combo, [store](int index) {
      if (index >= 0) store({static_cast<float>(index), 0.0f, 0.0f, 0.0f});
    });
    widget = combo;
    break;
  }
  }
  widget->setObjectName(QStringLiteral("parameter-") + QString::fromStdString(id));
  return widget;
}

} // namespace

std::map<QString, QPointer<QWidget>>
addParameterRows(QFormLayout& layout, const gpu::BrushManifest& brush,
                 const std::map<std::string, std::array<float, 4>>& values,
                 const QStringList& materials, const ParameterEdited& edited) {
  std::map<QString, QPointer<QWidget>> widgets;
  for (const gpu::BrushParameter& p : brush.parameters) {
    const auto value = values.find(p.id);
    QWidget* widget = makeParameterWidget(p, value != values.end() ? value->second : p.defaultValue,
                                          materials, edited);
    const QString tooltip = QString::fromStdString(p.tooltip);
    widget->setToolTip(tooltip);
    auto* label = new QLabel(QString::fromStdString(p.label));
    label->setToolTip(tooltip);
    label->setBuddy(widget);
    layout.addRow(label, widget);
    widgets[QString::fromStdString(p.id)] = widget;
  }
  return widgets;
}

QComboBox* makeNarrowCombo() {
  auto* combo = new QComboBox;
  combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo->setMinimumContentsLength(8);
  return combo;
}

} // namespace octaclay::app
