#pragma once

#include <stdexcept>
#include <string>

namespace octaclay::core {

/// What kind of failure an Error reports; the CLI maps each kind to its exit code.
enum class ErrorKind {
  InvalidArgument, ///< a parameter out of range (size not a power of two, unknown shape …)
  InvalidInput,    ///< a file that exists but is not what it should be
  Io,              ///< a file that cannot be opened, read, written or renamed
  UnknownId,       ///< a name that nothing loaded answers to (a brush id no brush has)
  Cancelled,       ///< the user stopped the work (a progress callback returned false)
};

/// Every failure core reports: a message that says what was wrong and what to do.
class Error : public std::runtime_error {
public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

private:
  ErrorKind kind_;
};

} // namespace octaclay::core
