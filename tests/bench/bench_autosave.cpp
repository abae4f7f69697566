// The modeller's autosave (app/gui/window/autosaver.h): the time the GUI thread spends in one
// (copying the document and handing it to the worker) against the time the worker then takes to
// encode and write it, at N = 1024 and 4096. The window goes on while the worker runs. No window,
// no X display: the autosaver and the recovery store alone. Times are the best of 5 runs.
#include "autosaver.h"
#include "recovery_store.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QCoreApplication>
#include <QTemporaryDir>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>

using namespace octaclay;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BM_Autosave(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  // A painted document: the diffuse layer holds texels, as after a paint stroke.
  core::Document document = core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n));
  document.diffuse.texels.assign(document.positions.texelCount() * 4, 0.5f);
  QTemporaryDir dir;
  app::RecoveryStore store(dir.path() + "/recovery", 0x7ffffff0);
  store.beginSession();
  app::Autosaver saver(store);
  double gui = 1e30, worker = 1e30;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    // What DocumentActions::autosaveNow does on the GUI thread.
    auto snapshot = std::make_shared<const core::Scene>(core::sceneOf(document));
    saver.start(std::move(snapshot), "/models/blob.exr");
    const double onGui = secondsSince(start);
    saver.wait();
    const double all = secondsSince(start);
    state.SetIterationTime(onGui);
    gui = std::min(gui, onGui);
    worker = std::min(worker, all - onGui);
  }
  state.counters["gui_ms"] = 1e3 * gui;
  state.counters["worker_ms"] = 1e3 * worker;
}

BENCHMARK(BM_Autosave)
    ->Arg(1024)
    ->Arg(4096)
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

} // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
