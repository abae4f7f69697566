#pragma once

#include "lod_display.h"

#include "octaclay/gpu/model_renderer.h"

#include <QObject>
#include <QPointer>

#include <array>

class QLabel;
class QWidget;

namespace octaclay::app {

/// The heat maps' colour scale as model_fragment.glsl's heatColour(): blue (0) through cyan,
/// green and yellow to red (1).
QColor heatColour(double s);

/// Small widgets over the viewport that say what its pixels mean: a colour legend while a heat
/// map (saliency, stretch) is shown, and "Full resolution" / "Level of detail" over the halves
/// side by side. They sit in the viewport's corners and follow its size.
class ViewportOverlay : public QObject {
  Q_OBJECT
public:
  explicit ViewportOverlay(QWidget* viewport);

  void setPreview(gpu::ModelView::Preview preview);
  void setLodDisplay(LodDisplay display);

  QWidget* legend() const { return legend_; }
  QLabel* leftLabel() const { return left_; }
  QLabel* rightLabel() const { return right_; }

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void place();
  std::array<QWidget*, 3> widgets() const;

  QWidget* viewport_;
  QWidget* legend_;
  QLabel *left_, *right_;
};

} // namespace octaclay::app
