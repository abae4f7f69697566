#include "mesh_size_dialog.h"

#include "octaclay/core/geometry/octahedral.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace octaclay::app {

MeshSizeDialog::MeshSizeDialog(Kind kind, int currentSize, QWidget* parent)
    : QDialog(parent), kind_(kind), current_(currentSize) {
  setObjectName(kind == Kind::Remesh ? "remeshDialog" : "resolutionDialog");
  setWindowTitle(kind == Kind::Remesh ? tr("Remesh") : tr("Resolution"));
  auto* layout = new QVBoxLayout(this);
  description_ = new QLabel(this);
  description_->setObjectName("description");
  description_->setWordWrap(true);
  description_->setMinimumWidth(420);
  layout->addWidget(description_);
  auto* form = new QFormLayout;
  sizes_ = new QComboBox(this);
  sizes_->setObjectName("size");
  const QLocale locale;
  // Within eight times the current N either way: a step of three doublings at most, and the
  // document's memory grows with N² (an 8192 image is 67 million samples).
  const int lowest = std::max(core::kMinSize, currentSize / 8);
  const int highest = std::min(core::kMaxSize, currentSize * 8);
  for (int n = lowest; n <= highest; n *= 2) {
    const qlonglong samples = qlonglong(n + 1) * qlonglong(n + 1);
    QString text = tr("%1 (%2 samples)").arg(n).arg(locale.toString(samples));
    if (n == currentSize) text += tr(", current");
    sizes_->addItem(text, n);
  }
  sizes_->setCurrentIndex(std::max(0, sizes_->findData(currentSize)));
  form->addRow(tr("New size N"), sizes_);
  layout->addLayout(form);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)
      ->setText(kind == Kind::Remesh ? tr("Remesh") : tr("Resample"));
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(sizes_, &QComboBox::currentIndexChanged, this, &MeshSizeDialog::describe);
  describe();
}

int MeshSizeDialog::size() const {
  return sizes_->currentData().toInt();
}

bool MeshSizeDialog::setSize(int n) {
  const int index = sizes_->findData(n);
  if (index < 0) return false;
  sizes_->setCurrentIndex(index);
  return true;
}

QList<int> MeshSizeDialog::sizes() const {
  QList<int> out;
  for (int i = 0; i < sizes_->count(); ++i)
    out << sizes_->itemData(i).toInt();
  return out;
}

QString MeshSizeDialog::description() const {
  return description_->text();
}

void MeshSizeDialog::describe() {
  const int n = size();
  QString text;
  if (kind_ == Kind::Remesh) {
    text = tr("Gives the current surface a new, even sampling: the surface is parameterized over "
              "the sphere again (as Import does) and resampled at N = %1, so stretched parts such "
              "as pulled limbs get their share of samples back. Every painted layer (colour, "
              "feature, mask) is carried to the same surface points.")
               .arg(n);
    text += QLatin1Char(' ');
    text += tr("If the surface would move beyond its tolerance, the model stays as it is and the "
               "status bar says why.");
  } else {
    text = n > current_ ? tr("Resamples every layer from N = %1 up to N = %2 with the same "
                             "parameterization: smooth interpolation, the existing samples "
                             "keep their values and the seams stay exact.")
                              .arg(current_)
                              .arg(n)
           : n < current_ ? tr("Resamples every layer from N = %1 down to N = %2 with the same "
                               "parameterization, filtered so that a later resize up comes back "
                               "close to this model; fine detail goes.")
                                .arg(current_)
                                .arg(n)
                          : tr("N = %1 is the current size: nothing to resample.").arg(n);
    text += QLatin1Char(' ');
    text += tr("Stretched parts stay stretched; Remesh evens the sampling out.");
  }
  text += QLatin1Char(' ');
  text += tr("Runs with progress and Cancel; one undo step brings the model back as it was.");
  description_->setText(text);
}

} // namespace octaclay::app
