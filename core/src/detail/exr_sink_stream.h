#pragma once

// An OpenEXR output stream straight into a staged file (ByteSink), through an 8 MiB buffer, so a
// document is never held twice in memory (ExrMemoryStream built the whole file first: 1.75 GB
// more at N = 8192). OpenEXR writes its offset table in OutputFile's destructor and swallows
// errors there, so the first failure is kept and finish() — called after the OutputFile is
// gone — throws it; nothing is taken as written before finish() returns.

#include "octaclay/core/document/atomic_output.h"

#include <ImfIO.h>

#include <cstdint>
#include <cstring>
#include <exception>
#include <vector>

namespace octaclay::core::detail {

class ExrSinkStream : public Imf::OStream {
public:
  explicit ExrSinkStream(ByteSink& sink) : Imf::OStream("document"), sink_(sink) {
    buffer_.reserve(kBufferBytes);
  }

  void write(const char c[], int n) override {
    if (error_) std::rethrow_exception(error_);
    if (position_ != bufferStart_ + buffer_.size()) flush();
    buffer_.insert(buffer_.end(), c, c + n);
    position_ += static_cast<std::uint64_t>(n);
    if (buffer_.size() >= kBufferBytes) flush();
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override {
    if (pos != position_) flush();
    position_ = pos;
    if (buffer_.empty()) bufferStart_ = pos;
  }

  /// Writes what is buffered and throws the first error any write met (Error(Io) from the sink).
  void finish() {
    flush();
    if (error_) std::rethrow_exception(error_);
  }

private:
  static constexpr std::size_t kBufferBytes = 8u << 20;

  void flush() {
    if (!buffer_.empty() && !error_) {
      try {
        sink_.writeAt(bufferStart_, std::span(reinterpret_cast<const std::uint8_t*>(buffer_.data()),
                                              buffer_.size()));
      } catch (...) {
        error_ = std::current_exception();
      }
    }
    buffer_.clear();
    bufferStart_ = position_;
    if (error_) std::rethrow_exception(error_);
  }

  ByteSink& sink_;
  std::vector<char> buffer_;
  std::uint64_t bufferStart_ = 0; ///< file offset of buffer_[0]
  std::uint64_t position_ = 0;
  std::exception_ptr error_;
};

} // namespace octaclay::core::detail
