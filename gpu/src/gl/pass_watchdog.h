#pragma once

// The GPU watchdog's wait: a fence after a brush pass, waited for with a time limit, so that a
// runaway shader is caught instead of hanging the caller.

#include <chrono>
#include <string>

namespace octaclay::gpu::detail {

/// Fences the GL commands issued so far and waits for them at most limit: whether they
/// finished in time. A limit of zero (or less) waits for nothing and returns true (the
/// watchdog is off). Throws GlError when the fence cannot be made or waited for.
bool finishedWithin(std::chrono::nanoseconds limit);

/// "2 s", "250 ms", "1 µs": a limit as a message shows it.
std::string describeLimit(std::chrono::nanoseconds limit);

} // namespace octaclay::gpu::detail
