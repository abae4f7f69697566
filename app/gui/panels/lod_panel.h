#pragma once

#include "lod_display.h"

#include "octaclay/core/lod/lod.h"
#include "octaclay/core/measure/surface_distance.h"

#include <QString>
#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace octaclay::app {

/// The Level-of-detail dock panel: which level of the document's N×N geometry image the
/// viewport draws (N/1, N/2, … N/32, levels of at least 2 samples a side, shown in words as
/// "Display detail: Low (128)", "N/8" in the item's tooltip), and the triangle counts of the
/// displayed and of the full mesh. The divisor is what the user chose; until they choose, it
/// follows each document to the largest level of at most 256 (the default display level).
///
/// Below, the automatic level of detail (thesis chapter 4): the resampling method (point,
/// average, salient average, salient point, adaptive, collapse, auto: the default), the
/// triangle target, what the viewport shows (the
/// full resolution, the LOD, or both side by side; the LOD is regenerated live while it is
/// shown), the LOD's triangles and generation time, its error against the full resolution
/// (as a percentage of the model's size; RMS, Hausdorff and PSNR in the tooltip) and Export…
/// (the LOD with its paint and a baked normal map). The methods are named in words ("Sharp
/// features"), their technical names in the items' tooltips. GUI thread.
class LodPanel : public QWidget {
  Q_OBJECT

public:
  /// The default displayed size: the largest level not above it is picked for a new document.
  static constexpr int kDefaultDisplaySize = 256;
  /// The coarsest level offered is N / kMaxDivisor.
  static constexpr int kMaxDivisor = 32;
  /// The automatic LOD's triangle target: its range and default (the live-LOD target).
  static constexpr int kMinTargetTriangles = 8, kMaxTargetTriangles = 10'000'000,
                       kDefaultTargetTriangles = 20'000;

  explicit LodPanel(QWidget* parent = nullptr);

  /// A new document: clears the LOD's figures (lodText(), errorText()) and lists the levels of
  /// an n×n document (n ≥ 2; below that the list is empty). Keeps the
  /// divisor the user chose (combo box or setDivisor) while it is still a level of n, else
  /// picks the largest level ≤ kDefaultDisplaySize (or the smallest level when none is).
  /// Emits levelChanged when the divisor changes.
  /// A torus or plane of n × height cells (height 0: square) lists the levels whose height/d
  /// keeps at least `leastCells` cells (a torus's 4), labelled W/d × H/d.
  void setDocumentSize(int n, int height = 0, int leastCells = 2);
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
  /// Forgets the level the user chose and shows the full resolution (not the LOD): the next
  /// setDocumentSize picks the default level again (File ▸ New starts from the defaults, not
  /// from the detail chosen for an imported or opened model). Emits displayChanged when the
  /// display changes.
  void forgetDisplayChoice();

  /// Shows "Displayed: 131,072 triangles" and "Full: 2,097,152 triangles" (numbers grouped as
  /// the default QLocale writes them). A displayed N-image has 2·N² triangles.
  void setTriangleCounts(long long displayed, long long full);
  QString displayedText() const;
  QString fullText() const;

  /// What the viewport shows.
  using Display = LodDisplay;
  Display display() const;
  /// Emits displayChanged when it changes.
  void setDisplay(Display display);
  /// Whether the LOD is wanted (shown alone or side by side): it is then kept up to date.
  bool lodShown() const { return display() != Display::FullResolution; }

  core::ResampleMethod method() const;
  /// Emits lodOptionsChanged when it changes.
  void setMethod(core::ResampleMethod method);
  /// The vertex-collapse target, 8 … 10,000,000 triangles (20,000 by default).
  int targetTriangles() const;
  /// Clamped to the range; emits lodOptionsChanged when it changes.
  void setTargetTriangles(int triangles);
  /// generateLod's options for the method and target (size chosen from the target).
  core::LodOptions lodOptions() const;
  /// The same for the live LOD: auto keeps to salient-point (LodOptions::autoMayCollapse).
  core::LodOptions liveLodOptions() const;
  /// Whether the live LOD of the chosen method reads the saliency.
  bool liveLodReadsSaliency() const;

  /// Shows "LOD: 20,000 triangles in 12.3 ms" for the newest LOD.
  void setLodResult(long long triangles, double milliseconds);
  /// Shows "Error (% of size): 0.123 % average, 1.01 % at most" (RMS and Hausdorff distance
  /// over the bounding-box diagonal; those and the PSNR in the tooltip), or "Error: —" when
  /// there is no measurement.
  void setLodError(const std::optional<core::SurfaceDistance>& error);
  QString lodText() const;
  QString errorText() const;

signals:
  /// The user or setDivisor/setDocumentSize changed the divisor.
  void levelChanged(int divisor);
  /// The method or the triangle target changed.
  void lodOptionsChanged();
  void displayChanged(octaclay::app::LodDisplay display);
  /// Export… was pressed.
  void exportRequested();

private:
  QWidget* buildAutomaticLod();
  bool isLevel(int divisor) const;
  void fillLevels();
  void applyDivisor(int divisor);

  int documentSize_ = 0;
  int documentHeight_ = 0; // a torus's or plane's H; 0 for a square image
  int leastCells_ = 2;     // cells a level keeps across H
  int divisor_ = 1;
  bool userChose_ = false;

  QComboBox* levelCombo_ = nullptr;
  QLabel* displayedLabel_ = nullptr;
  QLabel* fullLabel_ = nullptr;
  QComboBox* methodCombo_ = nullptr;
  QSpinBox* targetSpin_ = nullptr;
  QComboBox* displayCombo_ = nullptr;
  QLabel* lodLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QPushButton* exportButton_ = nullptr;
};

} // namespace octaclay::app
