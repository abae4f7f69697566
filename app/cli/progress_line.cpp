#include "progress_line.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace octaclay::app {

ProgressLine::ProgressLine(std::string command, bool enabled)
    : command_(std::move(command)), enabled_(enabled && ::isatty(STDERR_FILENO) == 1) {
  if (enabled_) ticker_ = std::thread([this] { run(); });
}

ProgressLine::~ProgressLine() {
  if (!enabled_) return;
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  ticker_.join();
  if (shown_) std::cerr << "\r\033[K" << std::flush; // the line goes; the report follows
}

void ProgressLine::stage(const std::string& name) {
  report(name, -1);
}

void ProgressLine::report(const std::string& name, float fraction) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  stage_ = name;
  fraction_ = fraction;
  done_ = -1;
}

void ProgressLine::count(const std::string& name, long long done, long long expected) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  stage_ = name;
  fraction_ = -1;
  done_ = done;
  expected_ = expected;
}

std::string ProgressLine::text() {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char line[256];
  if (done_ >= 0 && expected_ > 0)
    std::snprintf(line, sizeof line,
                  "%s: %s %lld of about %lld, %.0f s (Ctrl+C stops, nothing "
                  "is written)",
                  command_.c_str(), stage_.c_str(), done_, expected_, seconds);
  else if (done_ >= 0)
    std::snprintf(line, sizeof line, "%s: %s %lld, %.0f s (Ctrl+C stops, nothing is written)",
                  command_.c_str(), stage_.c_str(), done_, seconds);
  else if (fraction_ >= 0)
    std::snprintf(line, sizeof line, "%s: %s %d %%, %.0f s (Ctrl+C stops, nothing is written)",
                  command_.c_str(), stage_.c_str(), static_cast<int>(fraction_ * 100), seconds);
  else
    std::snprintf(line, sizeof line, "%s: %s, %.0f s (Ctrl+C stops, nothing is written)",
                  command_.c_str(), stage_.c_str(), seconds);
  return line;
}

void ProgressLine::run() {
  std::unique_lock lock(mutex_);
  // Quick work shows nothing: the first line comes after a second.
  if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_; })) return;
  while (!stopping_) {
    if (!stage_.empty()) {
      std::cerr << "\r\033[K" << text() << std::flush;
      shown_ = true;
    }
    wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; });
  }
}

} // namespace octaclay::app
