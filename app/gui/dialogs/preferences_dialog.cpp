#include "preferences_dialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace octaclay::app {

PreferencesDialog::PreferencesDialog(Values values, int minUndoMiB, int maxUndoMiB,
                                     const QString& inUse, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Preferences"));
  auto* form = new QFormLayout(this);
  undoMemory_ = new QSpinBox(this);
  undoMemory_->setObjectName(QStringLiteral("undoMemory"));
  undoMemory_->setRange(minUndoMiB, maxUndoMiB);
  undoMemory_->setSingleStep(64);
  undoMemory_->setSuffix(tr(" MiB"));
  undoMemory_->setValue(values.undoMiB);
  undoMemory_->setToolTip(tr("How much memory Undo may hold: when strokes no longer fit, the "
                             "oldest can no longer be undone. A step at N = 1024 takes a few "
                             "MiB."));
  form->addRow(tr("Undo memory"), undoMemory_);
  form->addRow(QString(), new QLabel(inUse));
  minutes_ = new QSpinBox(this);
  minutes_->setObjectName(QStringLiteral("autosaveMinutes"));
  minutes_->setRange(0, 60);
  minutes_->setSuffix(tr(" min"));
  minutes_->setSpecialValueText(tr("off"));
  minutes_->setValue(values.autosaveMinutes);
  form->addRow(tr("Autosave every"), minutes_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

PreferencesDialog::Values PreferencesDialog::values() const {
  return {undoMemory_->value(), minutes_->value()};
}

} // namespace octaclay::app
