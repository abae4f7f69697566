#pragma once

#include <QObject>
#include <QPointer>

class QWidget;

namespace octaclay::app {

/// Hands the keyboard back to the viewport when Esc is pressed in another widget of its window
/// (a spin box, slider or list in a dock), so the keys that follow (view keys, [ and ]) reach
/// the model instead of the box, and nothing is stroked. A left click on the viewport while a
/// spin box or line edit has the keys does the same: it takes the keys and makes no stroke.
/// Install on the application.
class ViewportFocusReturn : public QObject {
  Q_OBJECT
public:
  ViewportFocusReturn(QWidget* viewport, QObject* parent);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  QPointer<QWidget> viewport_;
  bool swallowPress_ = false; ///< the press that took the keys from a box makes no stroke
};

} // namespace octaclay::app
