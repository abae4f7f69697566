#pragma once

#include <QObject>
#include <QPointer>

class QWidget;

namespace octaclay::app {

/// Hands the keyboard back to the viewport when Esc is pressed in another widget of its window
/// (a spin box, slider or list in a dock), so the keys that follow (view keys, [ and ]) reach
/// the model instead of the box, and nothing is stroked. A left click on the viewport while a
/// spin box or line edit has the keys does the same: it takes the keys and makes no stroke.
/// Letting go of a slider there (the header's Radius and Strength, a dock's) hands the keys
/// back too, so [ and ] work at once after a drag on Strength. Install on the application.
class ViewportFocusReturn : public QObject {
  Q_OBJECT
public:
  ViewportFocusReturn(QWidget* viewport, QObject* parent);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  /// A widget outside the viewport in its window or a floating dock of it, not in a dialog.
  bool ours(QWidget* widget) const;

  QPointer<QWidget> viewport_;
  bool swallowPress_ = false; ///< the press that took the keys from a box makes no stroke
};

} // namespace octaclay::app
