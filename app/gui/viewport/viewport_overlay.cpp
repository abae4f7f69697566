#include "viewport_overlay.h"

#include <QEvent>
#include <QLabel>
#include <QLinearGradient>
#include <QPainter>
#include <QWidget>

#include <algorithm>

namespace octaclay::app {

QColor heatColour(double s) {
  const double r = std::clamp(4 * s - 2, 0.0, 1.0);
  const double g = std::clamp(s < 0.5 ? 4 * s : 4 - 4 * s, 0.0, 1.0);
  const double b = std::clamp(2 - 4 * s, 0.0, 1.0);
  return QColor::fromRgbF(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b));
}

namespace {

constexpr int kMargin = 10;

// A horizontal colour bar with a title above and its end values below.
class HeatLegend : public QWidget {
public:
  explicit HeatLegend(QWidget* parent) : QWidget(parent) {
    setObjectName("heatLegend");
    setAttribute(Qt::WA_TransparentForMouseEvents);
    resize(200, 58);
  }
  void setText(const QString& title, const QString& low, const QString& high) {
    title_ = title;
    low_ = low;
    high_ = high;
    update();
  }

protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.fillRect(rect(), QColor(20, 22, 26));
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 22, 26, 200));
    p.drawRoundedRect(rect(), 5, 5);
    const QRect bar(8, 24, width() - 16, 12);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    for (int k = 0; k <= 8; ++k)
      gradient.setColorAt(k / 8.0, heatColour(k / 8.0));
    p.fillRect(bar, gradient);
    p.setPen(Qt::white);
    p.drawText(QRect(8, 3, width() - 16, 20), Qt::AlignLeft | Qt::AlignVCenter, title_);
    p.drawText(QRect(8, 37, width() - 16, 18), Qt::AlignLeft | Qt::AlignVCenter, low_);
    p.drawText(QRect(8, 37, width() - 16, 18), Qt::AlignRight | Qt::AlignVCenter, high_);
  }

private:
  QString title_, low_, high_;
};

QLabel* halfLabel(const QString& text, const QString& name, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setObjectName(name);
  label->setAttribute(Qt::WA_TransparentForMouseEvents);
  label->setStyleSheet("QLabel { color: white; background: rgb(20, 22, 26); padding: 3px 8px; }");
  label->adjustSize();
  label->hide();
  return label;
}

} // namespace

ViewportOverlay::ViewportOverlay(QWidget* viewport)
    : QObject(viewport), viewport_(viewport), legend_(new HeatLegend(viewport)),
      left_(halfLabel(tr("Full resolution"), "fullResolutionLabel", viewport)),
      right_(halfLabel(tr("Level of detail"), "levelOfDetailLabel", viewport)) {
  legend_->hide();
  // The viewport's frames go to a native window (ViewportSurface): only native windows show
  // over it, and without blending, so the legend's corners are filled.
  for (QWidget* widget : widgets()) {
    widget->setAttribute(Qt::WA_DontCreateNativeAncestors);
    widget->setAttribute(Qt::WA_NativeWindow);
  }
  viewport->installEventFilter(this);
  place();
}

void ViewportOverlay::setPreview(gpu::ModelView::Preview preview) {
  auto* legend = static_cast<HeatLegend*>(legend_);
  if (preview == gpu::ModelView::Preview::Saliency)
    legend->setText(tr("Saliency"), tr("low"), tr("high"));
  else if (preview == gpu::ModelView::Preview::Stretch)
    legend->setText(tr("Sample spacing / mean"), tr("2× or less"), tr("4× or more"));
  legend_->setVisible(preview == gpu::ModelView::Preview::Saliency ||
                      preview == gpu::ModelView::Preview::Stretch);
  place();
}

void ViewportOverlay::setLodDisplay(LodDisplay display) {
  const bool sideBySide = display == LodDisplay::SideBySide;
  left_->setVisible(sideBySide);
  right_->setVisible(sideBySide);
  place();
}

bool ViewportOverlay::eventFilter(QObject* watched, QEvent* event) {
  if (watched == viewport_ && event->type() == QEvent::Resize) place();
  return QObject::eventFilter(watched, event);
}

std::array<QWidget*, 3> ViewportOverlay::widgets() const {
  return {legend_, left_, right_};
}

void ViewportOverlay::place() {
  const int w = viewport_->width(), h = viewport_->height();
  legend_->move(w - legend_->width() - kMargin, h - legend_->height() - kMargin);
  left_->move(kMargin, kMargin);
  right_->move(w / 2 + kMargin, kMargin);
  for (QWidget* widget : widgets())
    widget->raise();
}

} // namespace octaclay::app
