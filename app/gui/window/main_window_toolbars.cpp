// The main window's tool bars: the brush icons and the header (radius, strength, symmetry) above
// the viewport, both kept in step with the Brushes dock, and F / Shift+F on the canvas.

#include "brush_header.h"
#include "brush_panel.h"
#include "brush_toolbar.h"
#include "canvas_brush_adjust.h"
#include "main_window.h"
#include "modeller.h"
#include "viewport_widget.h"

#include "octaclay/gpu/brush_library.h"

#include <QAction>

namespace octaclay::app {

void MainWindow::buildToolBars() {
  auto* brushes = new BrushToolBar(this, this);
  // A row of icons, and under it the header, right above the viewport.
  addToolBar(Qt::TopToolBarArea, brushes);
  addToolBarBreak(Qt::TopToolBarArea);
  auto* header = new BrushHeader(this);
  addToolBar(Qt::TopToolBarArea, header);

  const auto fillBrushes = [this, brushes] {
    std::vector<gpu::BrushManifest> list;
    if (gpu::BrushLibrary* library = viewport_->modeller().library())
      for (const gpu::BrushManifest* b : library->brushes())
        list.push_back(*b);
    brushes->setBrushes(list);
    brushes->setCurrentBrush(brushPanel_->currentBrushId());
  };
  connect(&viewport_->modeller(), &Modeller::brushesChanged, this, fillBrushes);
  fillBrushes();
  connect(brushes, &BrushToolBar::brushChosen, brushPanel_, &BrushPanel::selectBrush);

  const auto showValues = [this, brushes, header] {
    brushes->setCurrentBrush(brushPanel_->currentBrushId());
    const BrushSettings s = brushPanel_->settings();
    header->setValues(s.radiusUnit, brushPanel_->radiusInUnit(), s.strength, s.symmetry);
  };
  connect(brushPanel_, &BrushPanel::settingsChanged, this, showValues);
  showValues();
  connect(header, &BrushHeader::radiusEdited, brushPanel_, &BrushPanel::setRadiusInUnit);
  connect(header, &BrushHeader::strengthEdited, brushPanel_, &BrushPanel::setStrength);
  connect(header, &BrushHeader::symmetryEdited, brushPanel_, &BrushPanel::setSymmetry);

  auto* adjust = new CanvasBrushAdjust(viewport_, brushPanel_, this);
  adjust->setObjectName(QStringLiteral("canvasBrushAdjust"));
  const auto addAdjust = [this, adjust](const QString& text, const QString& name,
                                        const QKeySequence& key, CanvasBrushAdjust::Mode mode) {
    auto* action = new QAction(text, this);
    action->setObjectName(name);
    action->setShortcut(key);
    action->setAutoRepeat(false); // holding the key must not restart the drag
    action->setToolTip(text);
    connect(action, &QAction::triggered, adjust, [adjust, mode] { adjust->begin(mode); });
    addAction(action);
  };
  addAdjust(tr("Brush Radius: Drag on the Canvas (click to set, Esc to cancel)"),
            QStringLiteral("actionAdjustRadius"), QKeySequence(Qt::Key_F),
            CanvasBrushAdjust::Mode::Radius);
  addAdjust(tr("Brush Strength: Drag on the Canvas (click to set, Esc to cancel)"),
            QStringLiteral("actionAdjustStrength"), QKeySequence(Qt::SHIFT | Qt::Key_F),
            CanvasBrushAdjust::Mode::Strength);
}

} // namespace octaclay::app
