// The Level-of-detail dock panel: a list of display levels and two triangle counts.

#include "lod_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>

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
  levelCombo_->setToolTip(tr("The level of detail the viewport draws while you work: N/k shows "
                             "every k-th sample of the N×N document. Brushes always edit the "
                             "full resolution."));
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
  form->addRow(tr("Display level"), levelCombo_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(displayedLabel_);
  layout->addWidget(fullLabel_);
  layout->addStretch(1);
}

void LodPanel::setDocumentSize(int n) {
  documentSize_ = std::max(n, 0);
  int divisor = divisor_;
  if (!userChose_ || !isLevel(divisor)) {
    // The largest level ≤ kDefaultDisplaySize, else the smallest level there is. A choice that
    // no longer fits is forgotten, so the next document gets the default again.
    userChose_ = false;
    divisor = 1;
    for (int d = 1; d <= kMaxDivisor && documentSize_ / d >= kMinLevelSize; d *= 2) {
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
  return documentSize_ == 0 || documentSize_ / divisor >= kMinLevelSize;
}

void LodPanel::fillLevels() {
  const QSignalBlocker block(levelCombo_);
  levelCombo_->clear();
  for (int d = 1; d <= kMaxDivisor && documentSize_ / d >= kMinLevelSize; d *= 2)
    levelCombo_->addItem(QStringLiteral("N/%1 (%2)").arg(d).arg(documentSize_ / d), d);
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
