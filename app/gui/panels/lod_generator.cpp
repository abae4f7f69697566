// The live level of detail: generateLod and the error readout on worker threads.
#include "lod_generator.h"

#include "octaclay/core/geometry/mesh_extraction.h"

#include <QtConcurrent/QtConcurrentRun>

#include <chrono>

namespace octaclay::app {

LodGenerator::LodGenerator(Snapshot snapshot, QObject* parent)
    : QObject(parent), snapshot_(std::move(snapshot)) {
  connect(&generation_, &QFutureWatcher<Generation>::finished, this,
          &LodGenerator::generationFinished);
  connect(&measurement_, &QFutureWatcher<Measurement>::finished, this,
          &LodGenerator::measurementFinished);
}

LodGenerator::~LodGenerator() {
  generation_.waitForFinished();
  measurement_.waitForFinished();
}

void LodGenerator::request() {
  requested_ = true;
  if (!generating_) startGeneration();
}

void LodGenerator::startGeneration() {
  requested_ = false;
  std::shared_ptr<const core::GeometryImage> image = snapshot_ ? snapshot_() : nullptr;
  if (!image) return;
  generating_ = true;
  generation_.setFuture(QtConcurrent::run([image, options = options_] {
    Generation g;
    g.image = image;
    const auto start = std::chrono::steady_clock::now();
    try {
      g.lod = std::make_shared<const core::LodMesh>(core::generateLod(*image, options));
    } catch (const std::exception& e) {
      g.error = QString::fromUtf8(e.what());
    }
    g.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return g;
  }));
}

void LodGenerator::generationFinished() {
  generating_ = false;
  const Generation g = generation_.result();
  if (!g.error.isEmpty()) {
    emit failed(g.error);
  } else {
    lod_ = g.lod;
    lodSource_ = g.image;
    measureDue_ = true;
    emit generated(g.lod, g.milliseconds);
  }
  if (requested_)
    startGeneration();
  else
    startMeasurement();
}

void LodGenerator::startMeasurement() {
  if (!measureDue_ || measuring_ || generating_ || !lod_) return;
  measureDue_ = false;
  measuring_ = true;
  measurement_.setFuture(
      QtConcurrent::run([image = lodSource_, lod = lod_, samples = errorSamples_] {
        Measurement m;
        try {
          core::SurfaceDistanceOptions options;
          options.samplesPerSurface = samples;
          m.distance = core::compareSurfaces(core::extractMesh(*image, 1), lod->mesh, options);
        } catch (const std::exception& e) {
          m.error = QString::fromUtf8(e.what());
        }
        return m;
      }));
}

void LodGenerator::measurementFinished() {
  measuring_ = false;
  const Measurement m = measurement_.result();
  if (m.error.isEmpty())
    emit measured(m.distance);
  else
    emit failed(m.error);
  if (!generating_) startMeasurement(); // a newer LOD came meanwhile
}

} // namespace octaclay::app
