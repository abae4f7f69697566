// The Level-of-detail dock panel: a list of display levels and two triangle counts.

#include "lod_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>
#include <utility>

namespace octaclay::app {

namespace {

constexpr int kMinLevelSize = 2;

bool isPowerOfTwo(int x) {
  return x > 0 && (x & (x - 1)) == 0;
}

// The default locale's digits and separators, grouped even where it omits grouping by default
// (the C locale): "2097152" is hard to read at a glance.
QString groupedNumber(long long value) {
  QLocale locale;
  QLocale::NumberOptions options = locale.numberOptions();
  options.setFlag(QLocale::OmitGroupSeparator, false);
  locale.setNumberOptions(options);
  return locale.toString(static_cast<qlonglong>(value));
}

} // namespace

LodPanel::LodPanel(QWidget* parent) : QWidget(parent) {
  levelCombo_ = new QComboBox;
  levelCombo_->setObjectName(QStringLiteral("level"));
  levelCombo_->setToolTip(tr("How much detail the viewport draws while you work (less draws "
                             "faster): N/k shows every k-th sample of the N×N model. Brushes "
                             "always edit the full detail."));
  levelCombo_->setEnabled(false);
  connect(levelCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0) return;
    userChose_ = true;
    applyDivisor(levelCombo_->itemData(index).toInt());
  });

  displayedLabel_ = new QLabel;
  displayedLabel_->setObjectName(QStringLiteral("displayedTriangles"));
  fullLabel_ = new QLabel;
  fullLabel_->setObjectName(QStringLiteral("fullTriangles"));
  displayedLabel_->setText(tr("Displayed: —"));
  fullLabel_->setText(tr("Full: —"));

  auto* form = new QFormLayout;
  form->addRow(tr("Display detail"), levelCombo_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(displayedLabel_);
  layout->addWidget(fullLabel_);
  layout->addWidget(buildAutomaticLod());
  layout->addStretch(1);
}

QWidget* LodPanel::buildAutomaticLod() {
  auto* box = new QGroupBox(tr("Automatic level of detail"));
  methodCombo_ = new QComboBox;
  methodCombo_->setObjectName(QStringLiteral("lodMethod"));
  // Words for the methods, no longer than the names were (they set the dock's width); the
  // technical name and what it does in each item's tooltip.
  const std::pair<core::ResampleMethod, QString> methods[] = {
      {core::ResampleMethod::Point, tr("Nearest sample")},
      {core::ResampleMethod::Average, tr("Smooth")},
      {core::ResampleMethod::SalientAverage, tr("Soft features")},
      {core::ResampleMethod::SalientPoint, tr("Sharp features")},
      {core::ResampleMethod::Adaptive, tr("Adaptive")},
      {core::ResampleMethod::Collapse, tr("Collapse")},
      {core::ResampleMethod::Auto, tr("Best")}};
  const QString whatEachDoes[] = {
      tr("the full-resolution sample at its place"),
      tr("the mean of the samples it stands for"),
      tr("their saliency-weighted mean"),
      tr("the most salient of them"),
      tr("vertices placed where the surface bends, no grid"),
      tr("edges collapsed on the full-resolution mesh"),
      tr("adaptive or collapse, whichever suits the model (the live view uses salient-point)")};
  for (std::size_t k = 0; k < std::size(methods); ++k) {
    methodCombo_->addItem(methods[k].second, static_cast<int>(methods[k].first));
    methodCombo_->setItemData(
        static_cast<int>(k),
        QStringLiteral("%1: %2").arg(QString::fromUtf8(core::methodName(methods[k].first)),
                                     whatEachDoes[k]),
        Qt::ToolTipRole);
  }
  // Never worse than meshoptimizer (issue 24): the export picks adaptive or the collapse per
  // image, the live LOD stays with salient-point.
  methodCombo_->setCurrentIndex(
      methodCombo_->findData(static_cast<int>(core::ResampleMethod::Auto)));
  methodCombo_->setToolTip(tr("How each LOD sample is picked from the full-resolution samples it "
                              "stands for: the one at its place, their mean, their "
                              "saliency-weighted mean, or the most salient one; adaptive "
                              "places its vertices where the surface bends, no grid; collapse "
                              "simplifies the full-resolution mesh; auto exports with adaptive "
                              "or collapse, whichever suits the image, and shows salient-point "
                              "live"));
  connect(methodCombo_, &QComboBox::currentIndexChanged, this,
          [this] { emit lodOptionsChanged(); });

  targetSpin_ = new QSpinBox;
  targetSpin_->setObjectName(QStringLiteral("lodTarget"));
  targetSpin_->setRange(kMinTargetTriangles, kMaxTargetTriangles);
  targetSpin_->setSingleStep(1000);
  targetSpin_->setValue(kDefaultTargetTriangles);
  targetSpin_->setGroupSeparatorShown(true);
  targetSpin_->setSuffix(tr(" triangles"));
  targetSpin_->setKeyboardTracking(false); // one regeneration per typed number, not per digit
  connect(targetSpin_, &QSpinBox::valueChanged, this, [this] { emit lodOptionsChanged(); });

  displayCombo_ = new QComboBox;
  displayCombo_->setObjectName(QStringLiteral("lodDisplay"));
  displayCombo_->addItems({tr("Full resolution"), tr("Level of detail"), tr("Side by side")});
  displayCombo_->setToolTip(tr("What the viewport shows; the level of detail follows your strokes "
                               "while it is shown"));
  connect(displayCombo_, &QComboBox::currentIndexChanged, this,
          [this](int index) { emit displayChanged(static_cast<Display>(std::max(index, 0))); });

  lodLabel_ = new QLabel(tr("LOD: —"));
  lodLabel_->setObjectName(QStringLiteral("lodTriangles"));
  errorLabel_ = new QLabel(tr("Error: —"));
  errorLabel_->setObjectName(QStringLiteral("lodError"));
  errorLabel_->setToolTip(tr("How far the LOD lies from the full-detail surface, as a percentage "
                             "of the model's size (its bounding-box diagonal)"));
  errorLabel_->setWordWrap(true);
  exportButton_ = new QPushButton(tr("Export…"));
  exportButton_->setObjectName(QStringLiteral("exportLod"));
  exportButton_->setToolTip(tr("Write the LOD as OBJ or GLB with its paint and a normal map baked "
                               "from the full resolution"));
  connect(exportButton_, &QPushButton::clicked, this, &LodPanel::exportRequested);

  auto* form = new QFormLayout;
  form->addRow(tr("Method"), methodCombo_);
  form->addRow(tr("Target"), targetSpin_);
  form->addRow(tr("Show"), displayCombo_);
  auto* layout = new QVBoxLayout(box);
  layout->addLayout(form);
  layout->addWidget(lodLabel_);
  layout->addWidget(errorLabel_);
  layout->addWidget(exportButton_);
  return box;
}

LodPanel::Display LodPanel::display() const {
  return static_cast<Display>(std::max(displayCombo_->currentIndex(), 0));
}

void LodPanel::setDisplay(Display display) {
  displayCombo_->setCurrentIndex(static_cast<int>(display));
}

core::ResampleMethod LodPanel::method() const {
  return static_cast<core::ResampleMethod>(methodCombo_->currentData().toInt());
}

void LodPanel::setMethod(core::ResampleMethod method) {
  methodCombo_->setCurrentIndex(methodCombo_->findData(static_cast<int>(method)));
}

int LodPanel::targetTriangles() const {
  return targetSpin_->value();
}

void LodPanel::setTargetTriangles(int triangles) {
  targetSpin_->setValue(triangles);
}

core::LodOptions LodPanel::lodOptions() const {
  core::LodOptions options;
  options.method = method();
  options.targetTriangles = static_cast<std::size_t>(targetTriangles());
  // size 0: the smallest M whose 2M² triangles reach the target, collapsed down to it.
  return options;
}

core::LodOptions LodPanel::liveLodOptions() const {
  core::LodOptions options = lodOptions();
  options.autoMayCollapse = false;
  return options;
}

bool LodPanel::liveLodReadsSaliency() const {
  const core::ResampleMethod m = method();
  return m == core::ResampleMethod::SalientPoint || m == core::ResampleMethod::SalientAverage ||
         m == core::ResampleMethod::Auto; // live auto is salient-point
}

void LodPanel::setLodResult(long long triangles, double milliseconds) {
  lodLabel_->setText(
      tr("LOD: %1 triangles in %2 ms").arg(groupedNumber(triangles)).arg(milliseconds, 0, 'f', 1));
}

void LodPanel::setLodError(const std::optional<core::SurfaceDistance>& error) {
  if (!error) {
    errorLabel_->setText(tr("Error: —"));
    errorLabel_->setToolTip(tr("How far the LOD lies from the full-detail surface, as a "
                               "percentage of the model's size (its bounding-box diagonal)"));
    return;
  }
  errorLabel_->setText(tr("Error (% of size): %1 % average, %2 % at most")
                           .arg(100 * error->rms, 0, 'g', 3)
                           .arg(100 * error->hausdorff, 0, 'g', 3));
  errorLabel_->setToolTip(tr("RMS %1 · Hausdorff %2 · PSNR %3 dB (two-sided distance to the "
                             "full-detail surface, as fractions of the bounding-box diagonal)")
                              .arg(error->rms, 0, 'g', 3)
                              .arg(error->hausdorff, 0, 'g', 3)
                              .arg(error->psnr, 0, 'f', 1));
}

QString LodPanel::lodText() const {
  return lodLabel_->text();
}

QString LodPanel::errorText() const {
  return errorLabel_->text();
}

void LodPanel::setDocumentSize(int n, int height, int leastCells) {
  documentSize_ = std::max(n, 0);
  documentHeight_ = std::max(height, 0);
  leastCells_ = std::max(leastCells, 1);
  // The figures were the previous document's.
  setLodError(std::nullopt);
  lodLabel_->setText(tr("LOD: —"));
  int divisor = divisor_;
  if (!userChose_ || !isLevel(divisor)) {
    // The largest level ≤ kDefaultDisplaySize, else the smallest level there is. A choice that
    // no longer fits is forgotten, so the next document gets the default again.
    userChose_ = false;
    divisor = 1;
    for (int d = 1; isLevel(d) && documentSize_ > 0; d *= 2) {
      divisor = d;
      if (documentSize_ / d <= kDefaultDisplaySize) break;
    }
  }
  fillLevels();
  applyDivisor(divisor);
}

bool LodPanel::setDivisor(int divisor) {
  if (!isLevel(divisor)) return false;
  userChose_ = true;
  applyDivisor(divisor);
  return true;
}

void LodPanel::forgetDisplayChoice() {
  userChose_ = false;
  setDisplay(Display::FullResolution);
}

void LodPanel::setTriangleCounts(long long displayed, long long full) {
  displayedLabel_->setText(tr("Displayed: %1 triangles").arg(groupedNumber(displayed)));
  fullLabel_->setText(tr("Full: %1 triangles").arg(groupedNumber(full)));
}

QString LodPanel::displayedText() const {
  return displayedLabel_->text();
}

QString LodPanel::fullText() const {
  return fullLabel_->text();
}

bool LodPanel::isLevel(int divisor) const {
  if (!isPowerOfTwo(divisor) || divisor > kMaxDivisor) return false;
  if (documentSize_ == 0) return true;
  return documentSize_ / divisor >= kMinLevelSize &&
         (documentHeight_ == 0 || documentHeight_ / divisor >= leastCells_);
}

void LodPanel::fillLevels() {
  const QSignalBlocker block(levelCombo_);
  levelCombo_->clear();
  const QString words[] = {tr("Full"), tr("High"),     tr("Medium"),
                           tr("Low"),  tr("Very low"), tr("Lowest")};
  int k = 0;
  for (int d = 1; documentSize_ > 0 && isLevel(d); d *= 2, ++k) {
    if (documentHeight_ > 0) { // a torus or plane: W × H cells
      const QString level = tr("%1 × %2").arg(documentSize_ / d).arg(documentHeight_ / d);
      levelCombo_->addItem(tr("%1 (%2)").arg(words[k], level), d);
      levelCombo_->setItemData(k,
                               tr("1/%1: one sample in %1 each way, %2 of the %3 × %4 model")
                                   .arg(d)
                                   .arg(level)
                                   .arg(documentSize_)
                                   .arg(documentHeight_),
                               Qt::ToolTipRole);
      continue;
    }
    levelCombo_->addItem(tr("%1 (%2)").arg(words[k]).arg(documentSize_ / d), d);
    const QString tip = d == 1 ? tr("N/1: every sample of the %1 × %1 model").arg(documentSize_)
                               : tr("N/%1: one sample in %1 each way, %2 × %2 of the %3 × %3 model")
                                     .arg(d)
                                     .arg(documentSize_ / d)
                                     .arg(documentSize_);
    levelCombo_->setItemData(k, tip, Qt::ToolTipRole);
  }
  levelCombo_->setEnabled(levelCombo_->count() > 0);
}

void LodPanel::applyDivisor(int divisor) {
  {
    const QSignalBlocker block(levelCombo_);
    levelCombo_->setCurrentIndex(levelCombo_->findData(divisor));
  }
  if (divisor == divisor_) return;
  divisor_ = divisor;
  emit levelChanged(divisor);
}

} // namespace octaclay::app
