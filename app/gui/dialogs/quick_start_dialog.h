#pragma once

#include <QDialog>

class QTextBrowser;

namespace octaclay::app {

/// Help ▸ Quick Start: a short illustrated page (sculpt, paint, undo, save, export), the HTML
/// page qrc:/help/quick_start.html compiled into the modeller (resources/help/).
class QuickStartDialog : public QDialog {
  Q_OBJECT
public:
  explicit QuickStartDialog(QWidget* parent = nullptr);
  QTextBrowser* browser() const { return browser_; }

private:
  QTextBrowser* browser_ = nullptr;
};

} // namespace octaclay::app
