#pragma once

#include <QDialog>
#include <QSize>
#include <QString>

class QCheckBox;
class QRadioButton;
class QSpinBox;

namespace octaclay::app {

/// What File ▸ Save Image draws.
struct ImageRequest {
  QSize size;             ///< device pixels
  bool background = true; ///< false: transparent background (alpha 0)
};

/// Asks the picture's size (the viewport's, or one typed in up to maxSide a side) and whether
/// it keeps the background.
class SaveImageDialog : public QDialog {
  Q_OBJECT
public:
  SaveImageDialog(QSize viewSize, int maxSide, QWidget* parent = nullptr);
  ImageRequest request() const;

private:
  QSize viewSize_;
  QRadioButton* viewSizeButton_ = nullptr;
  QSpinBox* width_ = nullptr;
  QSpinBox* height_ = nullptr;
  QCheckBox* transparent_ = nullptr;
};

} // namespace octaclay::app
