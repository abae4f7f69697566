#pragma once

// Progress of long work on a terminal (issue 34): one line on stderr, rewritten in place a few
// times a second once the work has taken a second, with the stage, how far it is and the time
// so far. Silent with --json, when stderr is not a terminal, or with --quiet.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace octaclay::app {

class ProgressLine {
public:
  /// command names the line ("relax"); shown only when enabled and stderr is a terminal.
  ProgressLine(std::string command, bool enabled);
  /// Stops the ticker and clears the line.
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// The stage now running ("reading", "relaxing", "measuring", "writing"), its fraction unknown.
  void stage(const std::string& name);
  /// The stage and how far it is, fraction in [0, 1].
  void report(const std::string& name, float fraction);
  /// The stage and a count of its items ("dabs"), expected 0 when unknown. Any thread.
  void count(const std::string& name, long long done, long long expected);

private:
  void run();
  std::string text();

  std::string command_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool shown_ = false;
  std::string stage_;
  float fraction_ = -1;
  long long done_ = -1, expected_ = 0;
  std::thread ticker_;
};

} // namespace octaclay::app
