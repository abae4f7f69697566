#pragma once

#include <QObject>
#include <QPointer>

class QWidget;

namespace octaclay::app {

/// Hands the keyboard back to the viewport when Esc is pressed in another widget of its window
/// (a spin box, slider or list in a dock), so the keys that follow (view keys, [ and ]) reach
/// the model instead of the box, and nothing is stroked. Install on the application.
class ViewportFocusReturn : public QObject {
  Q_OBJECT
public:
  ViewportFocusReturn(QWidget* viewport, QObject* parent);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  QPointer<QWidget> viewport_;
};

} // namespace octaclay::app
