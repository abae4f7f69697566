#include "quick_start_dialog.h"

#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

// The page lives in a static library: its resources are registered by name before first use
// (Q_INIT_RESOURCE must be called outside any namespace).
static void initHelpResources() {
  Q_INIT_RESOURCE(help);
}

namespace octaclay::app {

QuickStartDialog::QuickStartDialog(QWidget* parent) : QDialog(parent) {
  initHelpResources();
  setObjectName(QStringLiteral("quickStart"));
  setWindowTitle(tr("Quick Start"));
  browser_ = new QTextBrowser(this);
  browser_->setObjectName(QStringLiteral("quickStartPage"));
  browser_->setOpenExternalLinks(true);
  browser_->setSource(QUrl(QStringLiteral("qrc:/help/quick_start.html")));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(720, 640);
}

} // namespace octaclay::app
