#pragma once

#include "sculpt_session.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <memory>

namespace octaclay::app {

class Modeller;

/// The modeller's strokes through the session's one door (SculptSession): a stroke begins at a
/// press, its moves are queued as input arrives and run once per pass of the event loop (the
/// moves of one burst of pointer events coalesced, never inside a paint handler), and its end
/// solves keep detail's relaxation on a worker thread while the window keeps drawing and
/// answering; the step is recorded when the relaxation is in. A second stroke, an undo, a save
/// or anything that reads the document waits for it (settle()). GUI thread.
class StrokeDriver : public QObject {
  Q_OBJECT
public:
  explicit StrokeDriver(Modeller& modeller);
  ~StrokeDriver() override;

  /// Begins a stroke as start says (the previous one's relaxation settled first). Returns false
  /// (the modeller's error set) if the session refused it.
  bool begin(const StrokeStart& start);
  /// Queues a move; the queue runs at the next pass of the event loop (or at end()).
  void queue(const StrokeMove& move);
  /// Runs the queued moves now (GL made current here). Returns the dabs made.
  int runQueued();
  /// How end() waits for keep detail's relaxation: Wait finishes it before returning (a script,
  /// a test, a save), Background solves it on a worker (a mouse release).
  enum class Relax { Wait, Background };
  /// Ends the stroke: its last moves, then its relaxation and its history step.
  void end(Relax relax = Relax::Wait);
  /// Whether a stroke is being made or its relaxation solved.
  bool stroking() const;
  /// Whether a finished stroke's relaxation is being solved beside the GUI.
  bool relaxing() const { return ending_ != nullptr; }
  /// Waits for the relaxation, if one runs, and records its step.
  void settle();
  /// Whether the stroke's brush drags (after its first move, moves follow the pointer's rays).
  bool drags() const;

signals:
  /// A relaxation began (true) or its step was recorded (false): a busy cursor meanwhile.
  void relaxingChanged(bool relaxing);

private:
  void commit();

  Modeller& modeller_;
  bool runScheduled_ = false;
  bool inBackground_ = false;            // ending_'s relaxation runs on the worker
  std::unique_ptr<StrokeEnding> ending_; // its relaxation runs in relaxation_
  QFutureWatcher<void> relaxation_;
};

} // namespace octaclay::app
