#include "brush_bars.h"

#include "brush_header.h"
#include "brush_state.h"
#include "brush_toolbar.h"
#include "canvas_brush_adjust.h"
#include "viewport_widget.h"

#include <QAction>
#include <QMainWindow>

namespace octaclay::app {

void addBrushBars(QMainWindow& window, ViewportWidget& viewport, BrushState& state) {
  auto* brushes = new BrushToolBar(&window, &window);
  // A row of icons, and under it the header, right above the viewport.
  window.addToolBar(Qt::TopToolBarArea, brushes);
  window.addToolBarBreak(Qt::TopToolBarArea);
  auto* header = new BrushHeader(&window);
  window.addToolBar(Qt::TopToolBarArea, header);

  const auto showBrushes = [brushes, &state] {
    brushes->setBrushes(state.brushes());
    brushes->setCurrentBrush(state.currentBrushId());
  };
  QObject::connect(&state, &BrushState::brushesChanged, brushes, showBrushes);
  showBrushes();
  QObject::connect(brushes, &BrushToolBar::brushChosen, &state, &BrushState::selectBrush);

  const auto showValues = [brushes, header, &state] {
    brushes->setCurrentBrush(state.currentBrushId());
    header->setValues(state.radiusUnit(), state.radiusInUnit(), state.strength(),
                      state.settings().symmetry);
  };
  QObject::connect(&state, &BrushState::changed, header, showValues);
  showValues();
  QObject::connect(header, &BrushHeader::radiusEdited, &state, &BrushState::setRadiusInUnit);
  QObject::connect(header, &BrushHeader::strengthEdited, &state, &BrushState::setStrength);
  QObject::connect(header, &BrushHeader::symmetryEdited, &state, &BrushState::setSymmetry);

  QObject::connect(&viewport, &ViewportWidget::radiusStepRequested, &state,
                   [&state](float f) { state.setRadiusInUnit(state.radiusInUnit() * f); });
  QObject::connect(&viewport, &ViewportWidget::strengthStepRequested, &state,
                   [&state](float f) { state.setStrength(state.strength() * f); });

  auto* adjust = new CanvasBrushAdjust(&viewport, &state, &window);
  adjust->setObjectName(QStringLiteral("canvasBrushAdjust"));
  const auto addAdjust = [&window, adjust](const QString& text, const QString& name,
                                           const QKeySequence& key, CanvasBrushAdjust::Mode mode) {
    auto* action = new QAction(text, &window);
    action->setObjectName(name);
    action->setShortcut(key);
    action->setAutoRepeat(false); // holding the key must not restart the drag
    action->setToolTip(text);
    QObject::connect(action, &QAction::triggered, adjust, [adjust, mode] { adjust->begin(mode); });
    window.addAction(action);
  };
  addAdjust(QMainWindow::tr("Brush Radius: Drag on the Canvas (click to set, Esc to cancel)"),
            QStringLiteral("actionAdjustRadius"), QKeySequence(Qt::Key_F),
            CanvasBrushAdjust::Mode::Radius);
  addAdjust(QMainWindow::tr("Brush Strength: Drag on the Canvas (click to set, Esc to cancel)"),
            QStringLiteral("actionAdjustStrength"), QKeySequence(Qt::SHIFT | Qt::Key_F),
            CanvasBrushAdjust::Mode::Strength);
}

} // namespace octaclay::app
