#pragma once

#include <QString>
#include <QWidget>

class QComboBox;
class QLabel;

namespace octaclay::app {

/// The Level-of-detail dock panel: which level of the document's N×N geometry image the
/// viewport draws (N/1, N/2, … N/32, levels of at least 2 samples a side, shown as
/// "N/8 (128)"), and the triangle counts of the displayed and of the full mesh. The divisor is
/// what the user chose; until they choose, it follows each document to the largest level of
/// at most 256 (the default display level). GUI thread.
class LodPanel : public QWidget {
  Q_OBJECT

public:
  /// The default displayed size: the largest level not above it is picked for a new document.
  static constexpr int kDefaultDisplaySize = 256;
  /// The coarsest level offered is N / kMaxDivisor.
  static constexpr int kMaxDivisor = 32;

  explicit LodPanel(QWidget* parent = nullptr);

  /// Lists the levels of an n×n document (n ≥ 2; below that the list is empty). Keeps the
  /// divisor the user chose (combo box or setDivisor) while it is still a level of n, else
  /// picks the largest level ≤ kDefaultDisplaySize (or the smallest level when none is).
  /// Emits levelChanged when the divisor changes.
  void setDocumentSize(int n);
  /// The document size given to setDocumentSize; 0 before.
  int documentSize() const { return documentSize_; }

  /// N / displayedSize(): 1, 2, 4, 8, 16 or 32.
  int divisor() const { return divisor_; }
  /// documentSize() / divisor(): the size of the image the viewport draws.
  int displayedSize() const { return documentSize_ / divisor_; }
  /// Chooses a level by its divisor. Returns false, changing nothing, unless divisor is a power
  /// of two in [1, kMaxDivisor] that is a level of the current document (any such power of two
  /// when no document is set yet). Emits levelChanged when the divisor changes.
  bool setDivisor(int divisor);

  /// Shows "Displayed: 131,072 triangles" and "Full: 2,097,152 triangles" (numbers grouped as
  /// the default QLocale writes them). A displayed N-image has 2·N² triangles.
  void setTriangleCounts(long long displayed, long long full);
  QString displayedText() const;
  QString fullText() const;

signals:
  /// The user or setDivisor/setDocumentSize changed the divisor.
  void levelChanged(int divisor);

private:
  bool isLevel(int divisor) const;
  void fillLevels();
  void applyDivisor(int divisor);

  int documentSize_ = 0;
  int divisor_ = 1;
  bool userChose_ = false;

  QComboBox* levelCombo_ = nullptr;
  QLabel* displayedLabel_ = nullptr;
  QLabel* fullLabel_ = nullptr;
};

} // namespace octaclay::app
