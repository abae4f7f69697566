// The Brushes, Layers and Level-of-detail dock panels, offscreen: the real brush manifests fill
// the brush list and generate their widgets, a manifest with every parameter type gets the right
// widget classes and ranges, edits reach settings() and survive switching brushes and a new
// panel (QSettings, redirected to a temporary folder), load errors are shown in full, and the
// layers and level panels keep and persist their choices.

#include "brush_list.h"
#include "brush_panel.h"
#include "brush_state.h"
#include "color_button.h"
#include "layers_panel.h"
#include "lod_panel.h"

#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/stroke.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLocale>
#include <QRadioButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace octaclay;
using namespace octaclay::app;
namespace fs = std::filesystem;

namespace {

// Every built-in brush, parsed from the source tree, sorted by id (as the catalog hands them).
std::vector<gpu::BrushManifest> realBrushes() {
  std::vector<gpu::BrushManifest> brushes;
  for (const fs::directory_entry& entry :
       fs::directory_iterator(fs::path(OCTACLAY_SOURCE_DIR) / "plugins" / "brushes")) {
    const fs::path manifest = entry.path() / "manifest.json";
    if (fs::is_regular_file(manifest)) brushes.push_back(gpu::parseBrushManifest(manifest));
  }
  std::sort(brushes.begin(), brushes.end(),
            [](const gpu::BrushManifest& a, const gpu::BrushManifest& b) { return a.id < b.id; });
  return brushes;
}

// A brush with one parameter of every type and a falloff curve.
const char* const kEveryTypeManifest = R"({
  "id": "every-type",
  "name": "Every Type",
  "api": 1,
  "description": "One parameter of each type.",
  "category": "splat",
  "shader": "brush.glsl",
  "writes": ["diffuse"],
  "area": "uv",
  "falloff": "curve",
  "falloffCurve": [1.0, 0.5, 0.0],
  "parameters": [
    {"id": "depth", "label": "Depth", "type": "float", "default": 0.5, "min": -2, "max": 3,
     "step": 0.25, "tooltip": "How deep"},
    {"id": "count", "label": "Count", "type": "int", "default": 3, "min": 1, "max": 9,
     "tooltip": "How many"},
    {"id": "invert", "label": "Invert", "type": "bool", "default": true, "tooltip": "Flip it"},
    {"id": "tint", "label": "Tint", "type": "color", "default": [0.0, 0.5, 1.0, 1.0],
     "tooltip": "Which colour"},
    {"id": "mode", "label": "Mode", "type": "enum", "options": ["add", "sub", "mix"],
     "default": "sub", "tooltip": "How to combine"}
  ]
})";

gpu::BrushManifest writeAndParse(const QTemporaryDir& dir, const char* manifestText) {
  const fs::path folder = fs::path(dir.path().toStdString()) / "every-type";
  fs::create_directories(folder);
  std::ofstream(folder / "manifest.json", std::ios::binary) << manifestText;
  std::ofstream(folder / "brush.glsl", std::ios::binary)
      << "vec4 brush(vec4 v, BrushInput b) { return v; }\n";
  return gpu::parseBrushManifest(folder / "manifest.json");
}

bool nearlyEqual(const std::array<float, 4>& a, const std::array<float, 4>& b) {
  for (std::size_t c = 0; c < 4; ++c)
    if (std::abs(a[c] - b[c]) > 1e-3f) return false;
  return true;
}

std::array<float, 4> parameterOf(const BrushState& state, const std::string& id) {
  const BrushSettings s = state.settings();
  const auto it = s.parameters.find(id);
  return it != s.parameters.end() ? it->second : std::array<float, 4>{-1, -1, -1, -1};
}

QStringList childTexts(const QTreeWidgetItem* item) {
  QStringList out;
  for (int k = 0; k < item->childCount(); ++k)
    out.append(item->child(k)->text(0));
  return out;
}

} // namespace

class PanelsTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() {
    QVERIFY(settingsDir_.isValid());
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("OctaclayTests"));
    QCoreApplication::setApplicationName(QStringLiteral("panels_test"));
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir_.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QVERIFY2(QSettings().fileName().startsWith(settingsDir_.path()),
             qPrintable(QSettings().fileName()));
    brushes_ = realBrushes();
    QVERIFY(brushes_.size() >= 8);
  }

  void init() {
    QSettings settings;
    settings.clear();
    settings.sync();
  }

  void listsEveryBrushGroupedByCategory() {
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    QStringList expected;
    for (const gpu::BrushManifest& b : brushes_)
      expected.append(QString::fromStdString(b.id));
    QStringList listed = state.brushIds();
    listed.sort();
    expected.sort();
    QCOMPARE(listed, expected);

    const auto* list = panel.findChild<QTreeWidget*>(QStringLiteral("brushList"));
    QVERIFY(list);
    QCOMPARE(list->topLevelItemCount(), 3);
    QCOMPARE(list->topLevelItem(0)->text(0), QStringLiteral("Sculpt"));
    QCOMPARE(list->topLevelItem(1)->text(0), QStringLiteral("Paint"));
    QCOMPARE(list->topLevelItem(2)->text(0), QStringLiteral("Splat"));
    QVERIFY(childTexts(list->topLevelItem(1)).contains(QStringLiteral("Mask")));
    QVERIFY(childTexts(list->topLevelItem(1)).contains(QStringLiteral("Paint")));
    QCOMPARE(childTexts(list->topLevelItem(2)), (QStringList{"Material splat"}));
    QVERIFY(childTexts(list->topLevelItem(0)).contains(QStringLiteral("Sphere Add")));
    QCOMPARE(list->topLevelItem(0)->childCount() + list->topLevelItem(1)->childCount() +
                 list->topLevelItem(2)->childCount(),
             static_cast<int>(brushes_.size()));
    QCOMPARE(list->topLevelItem(1)->child(1)->data(0, Qt::UserRole).toString(),
             QStringLiteral("paint"));

    QCOMPARE(state.currentBrushId(), QStringLiteral("push"));
    QCOMPARE(state.settings().brushId, std::string("push"));
    QVERIFY(!panel.findChild<QWidget*>(QStringLiteral("brushErrors"))->isVisibleTo(&panel));

    // Without push the first listed brush is chosen; a brush that stays keeps its selection.
    std::vector<gpu::BrushManifest> noPush;
    for (const gpu::BrushManifest& b : brushes_)
      if (b.id != "push") noPush.push_back(b);
    QVERIFY(state.selectBrush(QStringLiteral("smooth")));
    state.setBrushes(noPush, {});
    QCOMPARE(state.currentBrushId(), QStringLiteral("smooth"));
    BrushState freshState;
    BrushPanel fresh(freshState);
    freshState.setBrushes(noPush, {});
    QCOMPARE(freshState.currentBrushId(), freshState.brushIds().front());
    QCOMPARE(freshState.currentBrushId(),
             QStringLiteral("clay-strips")); // the first sculpt brush by id
  }

  // The dock holds no values of its own: two docks viewing one state show every edit of either,
  // and a value set on the state (as the header, F-adjust and [ / ] do) shows in both.
  void theDockIsAViewOfTheBrushState() {
    BrushState state;
    BrushPanel left(state), right(state);
    state.setRadiusUnit(RadiusUnit::Scene);
    state.setBrushes(brushes_, {});
    QVERIFY(state.selectBrush(QStringLiteral("smooth")));
    const auto strengthOf = [](const BrushPanel& panel) {
      return panel.findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->value();
    };
    const auto currentOf = [](const BrushPanel& panel) {
      const auto* list = panel.findChild<QTreeWidget*>(QStringLiteral("brushList"));
      return list->currentItem() ? list->currentItem()->data(0, kBrushIdRole).toString()
                                 : QString();
    };
    QCOMPARE(currentOf(left), QStringLiteral("smooth"));
    QCOMPARE(currentOf(right), QStringLiteral("smooth"));

    left.findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->setValue(40.0);
    QCOMPARE(state.strength(), 0.4f);
    QCOMPARE(strengthOf(right), 40.0);

    state.setStrength(0.65f);
    QCOMPARE(strengthOf(left), 65.0);
    QCOMPARE(strengthOf(right), 65.0);

    right.findChild<QCheckBox*>(QStringLiteral("symmetryY"))->setChecked(true);
    QCOMPARE(state.settings().symmetry, unsigned(gpu::kSymmetryY));
    QVERIFY(left.findChild<QCheckBox*>(QStringLiteral("symmetryY"))->isChecked());

    const auto* list = right.findChild<QTreeWidget*>(QStringLiteral("brushList"));
    for (QTreeWidgetItemIterator it(const_cast<QTreeWidget*>(list)); *it; ++it)
      if ((*it)->data(0, kBrushIdRole).toString() == QStringLiteral("inflate"))
        const_cast<QTreeWidget*>(list)->setCurrentItem(*it);
    QCOMPARE(state.currentBrushId(), QStringLiteral("inflate"));
    QCOMPARE(currentOf(left), QStringLiteral("inflate"));
  }

  void selectingInTheListChangesTheBrush() {
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    QSignalSpy changed(&state, &BrushState::changed);
    auto* list = panel.findChild<QTreeWidget*>(QStringLiteral("brushList"));
    const QList<QTreeWidgetItem*> items =
        list->findItems(QStringLiteral("Mask"), Qt::MatchExactly | Qt::MatchRecursive);
    QCOMPARE(items.size(), 1);
    list->setCurrentItem(items.front());
    QCOMPARE(state.currentBrushId(), QStringLiteral("mask"));
    QCOMPARE(changed.count(), 1);
    QVERIFY(qobject_cast<QComboBox*>(panel.parameterWidget(QStringLiteral("mode"))));

    QVERIFY(!state.selectBrush(QStringLiteral("no-such-brush")));
    QCOMPARE(state.currentBrushId(), QStringLiteral("mask"));
    QCOMPARE(changed.count(), 1);
  }

  void paintBrushGetsAColourWidget() {
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    QVERIFY(!panel.parameterWidget(QStringLiteral("color")));
    QVERIFY(state.selectBrush(QStringLiteral("paint")));
    auto* button = qobject_cast<ColorButton*>(panel.parameterWidget(QStringLiteral("color")));
    QVERIFY(button);
    QCOMPARE(button->toolTip(), QStringLiteral("The colour laid down at full strength"));
    QVERIFY(std::abs(button->color().redF() - 0.8f) < 1e-3f);
    QVERIFY(std::abs(button->color().greenF() - 0.2f) < 1e-3f);
    QVERIFY(nearlyEqual(parameterOf(state, "color"), {0.8f, 0.2f, 0.1f, 1.0f}));
    // Its row is labelled with the manifest's label.
    bool labelled = false;
    for (const QLabel* label : panel.findChildren<QLabel*>())
      labelled =
          labelled || (label->text() == QStringLiteral("Colour") && label->buddy() == button);
    QVERIFY(labelled);

    // The manifest's area and falloff are the starting values.
    QCOMPARE(state.settings().area, gpu::AreaMode::Volume);
    QVERIFY(state.selectBrush(QStringLiteral("flatten")));
    QCOMPARE(state.settings().area, gpu::AreaMode::VolumeNormal);
    QVERIFY(state.selectBrush(QStringLiteral("sphere-add")));
    QCOMPARE(state.settings().falloff, gpu::Falloff::Constant);
    auto* falloff = panel.findChild<QComboBox*>(QStringLiteral("falloff"));
    QVERIFY(falloff);
    QCOMPARE(falloff->count(), 3); // no curve without a falloffCurve
    QCOMPARE(falloff->currentData().toInt(), static_cast<int>(gpu::Falloff::Constant));
  }

  void everyParameterTypeGetsItsWidget() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::vector<gpu::BrushManifest> brushes = brushes_;
    brushes.push_back(writeAndParse(dir, kEveryTypeManifest));
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes, {});
    QVERIFY(state.selectBrush(QStringLiteral("every-type")));

    auto* depth = qobject_cast<QDoubleSpinBox*>(panel.parameterWidget(QStringLiteral("depth")));
    QVERIFY(depth);
    QCOMPARE(depth->minimum(), -2.0);
    QCOMPARE(depth->maximum(), 3.0);
    QCOMPARE(depth->singleStep(), 0.25);
    QCOMPARE(depth->decimals(), 2);
    QCOMPARE(depth->value(), 0.5);
    QCOMPARE(depth->toolTip(), QStringLiteral("How deep"));

    auto* count = qobject_cast<QSpinBox*>(panel.parameterWidget(QStringLiteral("count")));
    QVERIFY(count);
    QCOMPARE(count->minimum(), 1);
    QCOMPARE(count->maximum(), 9);
    QCOMPARE(count->value(), 3);

    auto* invert = qobject_cast<QCheckBox*>(panel.parameterWidget(QStringLiteral("invert")));
    QVERIFY(invert);
    QVERIFY(invert->isChecked());

    auto* tint = qobject_cast<ColorButton*>(panel.parameterWidget(QStringLiteral("tint")));
    QVERIFY(tint);
    QCOMPARE(tint->color(), QColor::fromRgbF(0.0f, 0.5f, 1.0f, 1.0f));

    auto* mode = qobject_cast<QComboBox*>(panel.parameterWidget(QStringLiteral("mode")));
    QVERIFY(mode);
    QCOMPARE(mode->count(), 3);
    QCOMPARE(mode->itemText(2), QStringLiteral("mix"));
    QCOMPARE(mode->currentIndex(), 1);

    // The category is listed, and the curve is offered because the manifest has one.
    const auto* list = panel.findChild<QTreeWidget*>(QStringLiteral("brushList"));
    QCOMPARE(list->topLevelItem(2)->text(0), QStringLiteral("Splat"));
    auto* falloff = panel.findChild<QComboBox*>(QStringLiteral("falloff"));
    QCOMPARE(falloff->count(), 4);
    QCOMPARE(state.settings().falloff, gpu::Falloff::Curve);
    QCOMPARE(state.settings().area, gpu::AreaMode::Uv);

    // Each widget writes its parameter.
    QSignalSpy changed(&state, &BrushState::changed);
    depth->setValue(-1.25);
    QCOMPARE(parameterOf(state, "depth")[0], -1.25f);
    count->setValue(7);
    QCOMPARE(parameterOf(state, "count")[0], 7.0f);
    invert->setChecked(false);
    QCOMPARE(parameterOf(state, "invert")[0], 0.0f);
    tint->setColor(QColor::fromRgbF(0.25f, 0.5f, 0.75f, 0.5f));
    QVERIFY(nearlyEqual(parameterOf(state, "tint"), {0.25f, 0.5f, 0.75f, 0.5f}));
    mode->setCurrentIndex(2);
    QCOMPARE(parameterOf(state, "mode")[0], 2.0f);
    falloff->setCurrentIndex(falloff->findData(static_cast<int>(gpu::Falloff::Linear)));
    QCOMPARE(state.settings().falloff, gpu::Falloff::Linear);
    QCOMPARE(changed.count(), 6);

    // And a new panel reads them all back from QSettings.
    BrushState againState;
    BrushPanel again(againState);
    againState.setBrushes(brushes, {});
    QVERIFY(againState.selectBrush(QStringLiteral("every-type")));
    const BrushSettings s = againState.settings();
    QCOMPARE(s.parameters.at("depth")[0], -1.25f);
    QCOMPARE(s.parameters.at("count")[0], 7.0f);
    QCOMPARE(s.parameters.at("invert")[0], 0.0f);
    QVERIFY(nearlyEqual(s.parameters.at("tint"), {0.25f, 0.5f, 0.75f, 0.5f}));
    QCOMPARE(s.parameters.at("mode")[0], 2.0f);
    QCOMPARE(s.falloff, gpu::Falloff::Linear);
    QCOMPARE(
        qobject_cast<QComboBox*>(again.parameterWidget(QStringLiteral("mode")))->currentIndex(), 2);
  }

  void storedValuesAreFittedToTheManifest() {
    {
      QSettings settings;
      settings.setValue(QStringLiteral("brushes/mask/radius"), 7.0);
      settings.setValue(QStringLiteral("brushes/mask/falloff"), QStringLiteral("curve"));
      settings.setValue(QStringLiteral("brushes/mask/area"), QStringLiteral("uv"));
      settings.setValue(QStringLiteral("brushes/mask/parameters/mode"), QStringLiteral("erase"));
      settings.setValue(QStringLiteral("brushes/mask/parameters/gone"), 3.0);
    }
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    QVERIFY(state.selectBrush(QStringLiteral("mask")));
    const BrushSettings s = state.settings();
    QCOMPARE(s.radius, 1.0f);                  // clamped
    QCOMPARE(s.falloff, gpu::Falloff::Smooth); // no curve in this manifest: its own falloff
    QCOMPARE(s.area, gpu::AreaMode::Uv);
    QCOMPARE(s.parameters.size(), std::size_t(1));
    QCOMPARE(s.parameters.at("mode")[0], 1.0f); // the option "erase", stored by name
  }

  void valuesSurviveSwitchingBrushesAndANewPanel() {
    {
      BrushState state;
      BrushPanel panel(state);
      state.setBrushes(brushes_, {});
      QVERIFY(state.selectBrush(QStringLiteral("paint")));
      qobject_cast<ColorButton*>(panel.parameterWidget(QStringLiteral("color")))
          ->setColor(QColor::fromRgbF(0.1f, 0.9f, 0.3f, 1.0f));
      state.setStrength(0.8f);
      QVERIFY(state.selectBrush(QStringLiteral("push")));
      QCOMPARE(state.strength(), kDefaultSculptStrength); // push keeps its own
      state.setRadius(0.2f);
      QVERIFY(state.selectBrush(QStringLiteral("paint")));
      QCOMPARE(state.strength(), 0.8f);
      QCOMPARE(state.radius(), 0.05f);
      QVERIFY(nearlyEqual(parameterOf(state, "color"), {0.1f, 0.9f, 0.3f, 1.0f}));
      auto* button = qobject_cast<ColorButton*>(panel.parameterWidget(QStringLiteral("color")));
      QVERIFY(std::abs(button->color().greenF() - 0.9f) < 1e-3f);
      QCOMPARE(panel.findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->value(), 80.0);
      // Reloading the same brushes keeps what the panel remembers and the current brush.
      state.setBrushes(brushes_, {});
      QCOMPARE(state.currentBrushId(), QStringLiteral("paint"));
      QCOMPARE(state.strength(), 0.8f);
    }
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    QCOMPARE(state.radius(), 0.2f); // push, selected by default
    QVERIFY(state.selectBrush(QStringLiteral("paint")));
    QCOMPARE(state.strength(), 0.8f);
    QVERIFY(nearlyEqual(parameterOf(state, "color"), {0.1f, 0.9f, 0.3f, 1.0f}));
    QVERIFY(state.selectBrush(QStringLiteral("smooth")));
    QCOMPARE(state.radius(), 0.05f);
    QCOMPARE(state.strength(), kDefaultSculptStrength);
  }

  void draggingBrushesStartAtFullStrength() {
    QSettings().clear();
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    for (const char* id : {"snake-hook", "grab"}) {
      QVERIFY(state.selectBrush(QString::fromLatin1(id)));
      QCOMPARE(state.strength(), 1.0f);
      QCOMPARE(panel.findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->value(), 100.0);
    }
    QVERIFY(state.selectBrush(QStringLiteral("crease")));
    QCOMPARE(state.strength(), kDefaultSculptStrength);
  }

  void errorsAreShownInFull() {
    const std::string longError =
        "/home/someone/.local/share/octaclay/brushes/very-long-folder-name/manifest.json: "
        "parameters[2].type: unknown type \"vector\" (use float, int, bool, color or enum)";
    const std::string otherError = "/x/broken/manifest.json: invalid JSON at byte 17, line 2";
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {longError, otherError});
    auto* frame = panel.findChild<QWidget*>(QStringLiteral("brushErrors"));
    QVERIFY(frame);
    QVERIFY(frame->isVisibleTo(&panel));
    const QList<QLabel*> labels = panel.findChildren<QLabel*>(QStringLiteral("brushError"));
    QCOMPARE(labels.size(), 2);
    QStringList shown;
    for (const QLabel* label : labels) {
      QVERIFY(label->isVisibleTo(&panel));
      QVERIFY(label->wordWrap());
      shown.append(label->text().remove(QChar(0x200B)));
      QCOMPARE(label->property("error").toString(), shown.back());
    }
    QCOMPARE(shown,
             (QStringList{QString::fromStdString(longError), QString::fromStdString(otherError)}));
    QCOMPARE(state.errors(), shown);
    QCOMPARE(state.brushIds().size(), static_cast<qsizetype>(brushes_.size()));

    state.setBrushes(brushes_, {});
    QVERIFY(!frame->isVisibleTo(&panel));
    QVERIFY(panel.findChildren<QLabel*>(QStringLiteral("brushError")).isEmpty());

    // Only errors: still shown, and the form says there is no brush.
    state.setBrushes({}, {otherError});
    QVERIFY(frame->isVisibleTo(&panel));
    QVERIFY(state.currentBrushId().isEmpty());
    QVERIFY(state.settings().brushId.empty());
  }

  void setRadiusAndStrengthClampAndSignal() {
    BrushState state;
    BrushPanel panel(state);
    state.setBrushes(brushes_, {});
    state.setRadiusUnit(RadiusUnit::Scene); // the spin box in percent of the diagonal
    QSignalSpy changed(&state, &BrushState::changed);
    auto* radiusSpin = panel.findChild<QDoubleSpinBox*>(QStringLiteral("radius"));
    QVERIFY(radiusSpin);

    state.setRadius(5.0f);
    QCOMPARE(state.radius(), 1.0f);
    QCOMPARE(state.settings().radius, 1.0f);
    QCOMPARE(radiusSpin->value(), 100.0);
    QCOMPARE(changed.count(), 1);

    state.setRadius(0.0f);
    QCOMPARE(state.radius(), 0.001f);
    QCOMPARE(radiusSpin->value(), 0.1);
    QCOMPARE(changed.count(), 2);

    state.setRadius(0.125f);
    QCOMPARE(state.radius(), 0.125f);
    QCOMPARE(radiusSpin->value(), 12.5);
    QCOMPARE(changed.count(), 3);
    state.setRadius(0.125f); // unchanged: no signal
    QCOMPARE(changed.count(), 3);

    state.setStrength(-1.0f);
    QCOMPARE(state.strength(), 0.0f);
    state.setStrength(2.0f);
    QCOMPARE(state.strength(), 1.0f);
    QCOMPARE(changed.count(), 5);

    // Editing the spin box is the same as the setter.
    radiusSpin->setValue(30.0);
    QCOMPARE(state.radius(), 0.3f);
    QCOMPARE(changed.count(), 6);
  }

  // Issue 31: the radius in view pixels is a new user's unit; the unit is shared by every brush
  // and kept, each brush keeps its radius in both units, and a user whose brushes already have
  // stored values keeps the diagonal's unit they had.
  void radiusUnitIsTheViewForANewUserAndKept() {
    {
      BrushState state;
      BrushPanel panel(state);
      state.setBrushes(brushes_, {});
      QCOMPARE(state.radiusUnit(), RadiusUnit::View);
      QCOMPARE(state.settings().radiusUnit, RadiusUnit::View);
      QCOMPARE(state.settings().radiusPixels, kDefaultRadiusPixels);
      auto* spin = panel.findChild<QDoubleSpinBox*>(QStringLiteral("radius"));
      auto* unit = panel.findChild<QComboBox*>(QStringLiteral("radiusUnit"));
      QVERIFY(spin && unit);
      QCOMPARE(spin->value(), double(kDefaultRadiusPixels));
      QCOMPARE(spin->suffix(), QStringLiteral(" px"));
      QSignalSpy changed(&state, &BrushState::changed);
      spin->setValue(55.0); // typed: the view radius
      QCOMPARE(state.radiusPixels(), 55.0f);
      QCOMPARE(state.radius(), 0.05f);
      state.setRadiusInUnit(5000.0f); // clamped
      QCOMPARE(state.radiusPixels(), kMaxRadiusPixels);
      state.setRadiusInUnit(0.0f);
      QCOMPARE(state.radiusPixels(), kMinRadiusPixels);
      state.setRadiusPixels(55.0f);
      QCOMPARE(changed.count(), 4);
      // The unit chosen beside the radius: the spin box then shows percent.
      unit->setCurrentIndex(unit->findData(static_cast<int>(RadiusUnit::Scene)));
      QCOMPARE(state.radiusUnit(), RadiusUnit::Scene);
      QCOMPARE(changed.count(), 5);
      QCOMPARE(spin->suffix(), QStringLiteral(" %"));
      QCOMPARE(spin->value(), 5.0);
      QCOMPARE(state.radiusInUnit(), 0.05f);
      QVERIFY(state.selectBrush(QStringLiteral("paint"))); // shared by every brush
      QCOMPARE(state.settings().radiusUnit, RadiusUnit::Scene);
    }
    {
      BrushState state;
      BrushPanel panel(state); // a new start reads both back
      state.setBrushes(brushes_, {});
      QVERIFY(state.selectBrush(QStringLiteral("push")));
      QCOMPARE(state.radiusUnit(), RadiusUnit::Scene);
      QCOMPARE(state.radiusPixels(), 55.0f);
      state.setRadiusUnit(RadiusUnit::View);
    }
    QCOMPARE(BrushValueStore::loadRadiusUnit(), RadiusUnit::View);
    // A user from before the unit: stored brush values and no unit keep the diagonal's.
    QSettings().remove(QStringLiteral("brushes/radiusUnit"));
    QCOMPARE(BrushValueStore::loadRadiusUnit(), RadiusUnit::Scene);
    QSettings().clear();
    QCOMPARE(BrushValueStore::loadRadiusUnit(), RadiusUnit::View);
  }

  void strokeOptionsAreSharedAndPersisted() {
    {
      BrushState state;
      BrushPanel panel(state);
      state.setBrushes(brushes_, {});
      QCOMPARE(state.settings().pressureTarget, PressureTarget::Strength);
      QSignalSpy changed(&state, &BrushState::changed);
      panel.findChild<QComboBox*>(QStringLiteral("pressureTarget"))->setCurrentIndex(1);
      panel.findChild<QSlider*>(QStringLiteral("stabilizer"))->setValue(40);
      panel.findChild<QCheckBox*>(QStringLiteral("symmetryX"))->setChecked(true);
      panel.findChild<QCheckBox*>(QStringLiteral("symmetryZ"))->setChecked(true);
      QCOMPARE(changed.count(), 4);
      QVERIFY(state.selectBrush(QStringLiteral("smooth")));
      const BrushSettings s = state.settings();
      QCOMPARE(s.pressureTarget, PressureTarget::Radius);
      QCOMPARE(s.stabilizer, 0.4f);
      QCOMPARE(s.symmetry, 5u);
    }
    BrushState state;
    BrushPanel panel(state);
    const BrushSettings s = state.settings();
    QCOMPARE(s.pressureTarget, PressureTarget::Radius);
    QCOMPARE(s.stabilizer, 0.4f);
    QCOMPARE(s.symmetry, 5u);
    QVERIFY(panel.findChild<QCheckBox*>(QStringLiteral("symmetryZ"))->isChecked());
    QVERIFY(!panel.findChild<QCheckBox*>(QStringLiteral("symmetryY"))->isChecked());
    state.setSymmetry(2u | 8u);
    QCOMPARE(state.settings().symmetry, 2u);
  }

  void keepDetailIsOnByDefaultAndPersisted() {
    {
      BrushState state;
      BrushPanel panel(state);
      state.setBrushes(brushes_, {});
      QVERIFY(state.settings().keepDetail);
      auto* box = panel.findChild<QCheckBox*>(QStringLiteral("keepDetail"));
      QVERIFY(box);
      QVERIFY(box->isChecked());
      QVERIFY(box->toolTip().contains(QStringLiteral("keeps its detail")));
      QVERIFY(
          box->toolTip().contains(QStringLiteral("Off: samples stay where the brush put them")));
      QSignalSpy changed(&state, &BrushState::changed);
      box->setChecked(false);
      QCOMPARE(changed.count(), 1);
      QVERIFY(!state.settings().keepDetail);
      state.setKeepDetail(false); // unchanged: no signal
      QCOMPARE(changed.count(), 1);
      QVERIFY(state.selectBrush(QStringLiteral("smooth"))); // shared by every brush
      QVERIFY(!state.settings().keepDetail);
    }
    {
      BrushState state;
      BrushPanel panel(state); // a new session reads it back
      QVERIFY(!state.settings().keepDetail);
      QVERIFY(!panel.findChild<QCheckBox*>(QStringLiteral("keepDetail"))->isChecked());
      QSignalSpy changed(&state, &BrushState::changed);
      state.setKeepDetail(true);
      QCOMPARE(changed.count(), 1);
      QVERIFY(panel.findChild<QCheckBox*>(QStringLiteral("keepDetail"))->isChecked());
    }
    QVERIFY(BrushState().settings().keepDetail);
  }

  void layersKeepAndPersistVisibilityAndTarget() {
    using core::EditLayer;
    {
      LayersPanel panel;
      QCOMPARE(panel.paintTarget(), core::EditLayer::Diffuse);
      for (const core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                          core::EditLayer::Feature, core::EditLayer::Mask})
        QVERIFY(panel.isVisible(layer));
      auto* positions = panel.findChild<QCheckBox*>(QStringLiteral("visible-positions"));
      QVERIFY(positions);
      QVERIFY(positions->isChecked());
      QVERIFY(!positions->isEnabled());

      QSignalSpy visibility(&panel, &LayersPanel::visibilityChanged);
      QSignalSpy target(&panel, &LayersPanel::paintTargetChanged);
      panel.setVisible(core::EditLayer::Positions, false);
      QVERIFY(panel.isVisible(core::EditLayer::Positions));
      QCOMPARE(visibility.count(), 0);
      panel.setVisible(core::EditLayer::Mask, false);
      QVERIFY(!panel.isVisible(core::EditLayer::Mask));
      QVERIFY(!panel.findChild<QCheckBox*>(QStringLiteral("visible-mask"))->isChecked());
      panel.findChild<QCheckBox*>(QStringLiteral("visible-feature"))->setChecked(false);
      QVERIFY(!panel.isVisible(core::EditLayer::Feature));
      QCOMPARE(visibility.count(), 2);

      panel.findChild<QRadioButton*>(QStringLiteral("target-feature"))->setChecked(true);
      QCOMPARE(panel.paintTarget(), core::EditLayer::Feature);
      QCOMPARE(target.count(), 1);
      QVERIFY(!panel.findChild<QRadioButton*>(QStringLiteral("target-diffuse"))->isChecked());
      panel.setPaintTarget(core::EditLayer::Positions); // not paintable: ignored
      QCOMPARE(panel.paintTarget(), core::EditLayer::Feature);
      QCOMPARE(target.count(), 1);

      QCOMPARE(panel.layerStateText(core::EditLayer::Diffuse), QStringLiteral("uniform"));
      panel.setLayerState(core::EditLayer::Diffuse, true);
      QVERIFY(panel.isPainted(core::EditLayer::Diffuse));
      QCOMPARE(panel.layerStateText(core::EditLayer::Diffuse), QStringLiteral("painted"));
      QCOMPARE(panel.findChild<QLabel*>(QStringLiteral("state-diffuse"))->text(),
               QStringLiteral("painted"));
    }
    LayersPanel panel;
    QCOMPARE(panel.paintTarget(), core::EditLayer::Feature);
    QVERIFY(panel.findChild<QRadioButton*>(QStringLiteral("target-feature"))->isChecked());
    QVERIFY(!panel.isVisible(core::EditLayer::Mask));
    QVERIFY(!panel.isVisible(core::EditLayer::Feature));
    QVERIFY(panel.isVisible(core::EditLayer::Diffuse));
    QVERIFY(!panel.findChild<QCheckBox*>(QStringLiteral("visible-mask"))->isChecked());
    QVERIFY(!panel.isPainted(core::EditLayer::Diffuse)); // state is the document's, not persisted
  }

  // The preview list's rows are Preview's values in order; Stretch is the last.
  void layersPreviewListsEveryPreviewInOrder() {
    LayersPanel panel;
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("preview"));
    QVERIFY(combo);
    QCOMPARE(combo->count(), static_cast<int>(LayersPanel::Preview::Stretch) + 1);
    QCOMPARE(combo->itemText(6), QStringLiteral("Saliency"));
    QCOMPARE(combo->itemText(7), QStringLiteral("Stretch"));
    QVERIFY(combo->toolTip().contains(QStringLiteral("stretch")));
    QSignalSpy changed(&panel, &LayersPanel::previewChanged);
    panel.setPreview(LayersPanel::Preview::Stretch);
    QCOMPARE(combo->currentIndex(), 7);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.front().front().value<LayersPanel::Preview>(), LayersPanel::Preview::Stretch);
  }

  void lodListsLevelsAndCounts() {
    LodPanel panel;
    QSignalSpy level(&panel, &LodPanel::levelChanged);
    panel.setDocumentSize(1024);
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("level"));
    QVERIFY(combo);
    QStringList texts;
    for (int k = 0; k < combo->count(); ++k)
      texts.append(combo->itemText(k));
    QCOMPARE(texts, (QStringList{"Full (1024)", "High (512)", "Medium (256)", "Low (128)",
                                 "Very low (64)", "Lowest (32)"}));
    // The technical level in each item's tooltip.
    QCOMPARE(combo->itemData(2, Qt::ToolTipRole).toString(),
             QStringLiteral("N/4: one sample in 4 each way, 256 × 256 of the 1024 × 1024 model"));
    QCOMPARE(panel.divisor(), 4);
    QCOMPARE(panel.displayedSize(), 256);
    QCOMPARE(combo->currentText(), QStringLiteral("Medium (256)"));
    QCOMPARE(level.count(), 1);
    QCOMPARE(level.front().front().toInt(), 4);

    const QLocale previous;
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    const long long displayed = 2LL * panel.displayedSize() * panel.displayedSize();
    panel.setTriangleCounts(displayed, 2LL * 1024 * 1024);
    QLocale::setDefault(previous);
    QCOMPARE(panel.displayedText(), QStringLiteral("Displayed: 131,072 triangles"));
    QCOMPARE(panel.fullText(), QStringLiteral("Full: 2,097,152 triangles"));

    // Small documents offer only levels of at least 2 samples and default to full size.
    panel.setDocumentSize(8);
    QCOMPARE(combo->count(), 3);
    QCOMPARE(combo->itemText(2), QStringLiteral("Medium (2)"));
    QCOMPARE(panel.divisor(), 1);
    QCOMPARE(level.count(), 2);

    // A level the user chose is kept while it exists.
    combo->setCurrentIndex(1);
    QCOMPARE(panel.divisor(), 2);
    QCOMPARE(level.count(), 3);
    panel.setDocumentSize(2048);
    QCOMPARE(panel.divisor(), 2);
    QCOMPARE(panel.displayedSize(), 1024);
    QCOMPARE(level.count(), 3);
    panel.setDocumentSize(2); // N/2 would be 1 sample
    QCOMPARE(panel.divisor(), 1);
    QCOMPARE(combo->count(), 1);

    // A 64 × 16 torus: levels keep 4 cells around its tube, labelled W/d × H/d; a chosen level
    // it lacks falls back to the default.
    panel.setDocumentSize(64, 16, 4);
    QCOMPARE(combo->count(), 3);
    QCOMPARE(combo->itemText(0), QStringLiteral("Full (64 × 16)"));
    QCOMPARE(combo->itemText(2), QStringLiteral("Medium (16 × 4)"));
    QVERIFY(!panel.setDivisor(8)); // 8 × 2: too thin a ring
    QVERIFY(panel.setDivisor(4));
    QCOMPARE(panel.displayedSize(), 16);

    panel.setDocumentSize(4096);
    QVERIFY(!panel.setDivisor(3));
    QVERIFY(!panel.setDivisor(64));
    QVERIFY(panel.setDivisor(16));
    QCOMPARE(panel.displayedSize(), 256);
    QCOMPARE(combo->currentData().toInt(), 16);
    QCOMPARE(level.back().front().toInt(), 16);
  }

private:
  QTemporaryDir settingsDir_;
  std::vector<gpu::BrushManifest> brushes_;
};

QTEST_MAIN(PanelsTest)
#include "panels_test.moc"
