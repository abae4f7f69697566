#pragma once

// The GPU watchdog: a fence after each brush pass, checked against a time limit measured from
// the pass's submission, so that a runaway shader is caught instead of hanging the caller, and
// without the CPU waiting for each pass as it is issued.

#include <chrono>
#include <cstdint>
#include <deque>
#include <string>

namespace octaclay::gpu::detail {

/// The passes issued and not yet known to be finished, each with its fence, its submission
/// time and what issued it. A pass counts as overrun when it has not finished `limit` after its
/// submission: its fence unsignalled by then, or the GPU's clock at its completion (a timestamp
/// query) past it. Use it on the thread whose GL context is current.
class PassWatchdog {
public:
  PassWatchdog() = default;
  ~PassWatchdog();
  PassWatchdog(const PassWatchdog&) = delete;
  PassWatchdog& operator=(const PassWatchdog&) = delete;

  /// Fences the GL commands issued so far: a pass by `owner` (a brush id) was just submitted. A
  /// limit of zero (or less) fences nothing: the watchdog is off. Throws GlError when the fence
  /// cannot be made.
  void submitted(std::chrono::nanoseconds limit, const std::string& owner);
  /// Waits until at most `ahead` fenced passes may still run: each older one is waited for up
  /// to the limit less the time since its submission (a pass the GPU finished meanwhile costs
  /// no wait). Returns the owner of the first one that overran, the fences all forgotten, or
  /// nullptr when all finished in time. ahead = 0 before the CPU reads what the passes wrote;
  /// ahead = 1 lets the GPU run one pass ahead of the CPU. Throws GlError when a fence cannot be
  /// waited for.
  const std::string* keepWithin(std::size_t ahead, std::chrono::nanoseconds limit);
  /// Forgets every fence (the passes run on unwatched).
  void clear();
  std::size_t pending() const { return pending_.size(); }

private:
  struct Pending {
    void* fence;               // GLsync
    unsigned query;            // a GL_TIMESTAMP query after the pass: when it completed
    std::int64_t gpuSubmitted; // the GPU's clock (ns) at submission
    std::chrono::steady_clock::time_point submitted;
    std::string owner;
  };
  std::deque<Pending> pending_;
  std::string overran_;
};

/// "2 s", "250 ms", "1 µs": a limit as a message shows it.
std::string describeLimit(std::chrono::nanoseconds limit);

} // namespace octaclay::gpu::detail
