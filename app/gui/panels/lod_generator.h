#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/measure/surface_distance.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace octaclay::app {

/// Keeps a level of detail of the edited document up to date off the GUI thread (thesis 4:
/// "real time generation of differing levels of detail"). request() marks the surface changed;
/// one generation (core::generateLod on a snapshot of the positions, taken when it starts) runs
/// at a time, and requests made meanwhile fold into one that starts when it ends, so a stroke
/// gets a new LOD as often as generation allows. When no request is waiting, the newest LOD's
/// error against the full resolution is measured, also in the background. GUI thread.
class LodGenerator : public QObject {
  Q_OBJECT
public:
  using Snapshot = std::function<std::shared_ptr<const core::GeometryImage>()>;

  /// snapshot returns the current positions (with saliency) or null when there is no document.
  explicit LodGenerator(Snapshot snapshot, QObject* parent = nullptr);
  /// Waits for running work.
  ~LodGenerator() override;

  /// Takes effect with the next generation; call request() to regenerate.
  void setOptions(const core::LodOptions& options) { options_ = options; }
  const core::LodOptions& options() const { return options_; }
  /// Points sampled on each surface for the error readout (compareSurfaces).
  void setErrorSamples(std::size_t samples) { errorSamples_ = samples; }

  /// The surface or the options changed: regenerate (now, or after the running generation).
  void request();
  /// Whether a generation or measurement runs or waits.
  bool busy() const { return generating_ || measuring_ || requested_; }

  /// The newest LOD (null before the first) and the positions it was made from.
  std::shared_ptr<const core::LodMesh> lod() const { return lod_; }
  std::shared_ptr<const core::GeometryImage> lodSource() const { return lodSource_; }

signals:
  /// A new LOD: its generation took milliseconds (snapshot + generateLod, on the worker).
  void generated(std::shared_ptr<const core::LodMesh> lod, double milliseconds);
  /// The newest LOD's distance to the full-resolution surface.
  void measured(core::SurfaceDistance error);
  void failed(const QString& message);

private:
  struct Generation {
    std::shared_ptr<const core::GeometryImage> image;
    std::shared_ptr<const core::LodMesh> lod;
    double milliseconds = 0;
    QString error;
  };
  struct Measurement {
    core::SurfaceDistance distance;
    QString error;
  };
  void startGeneration();
  void generationFinished();
  void startMeasurement();
  void measurementFinished();

  Snapshot snapshot_;
  core::LodOptions options_;
  std::size_t errorSamples_ = 100'000;
  QFutureWatcher<Generation> generation_;
  QFutureWatcher<Measurement> measurement_;
  bool requested_ = false, generating_ = false, measuring_ = false, measureDue_ = false;
  std::shared_ptr<const core::GeometryImage> lodSource_; // the positions lod_ was made from
  std::shared_ptr<const core::LodMesh> lod_;
};

} // namespace octaclay::app
