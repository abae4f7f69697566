#pragma once

// An OpenEXR output stream into memory: OpenEXR writes its offset table in OutputFile's
// destructor and swallows errors there, so EXR files are built in memory and handed to the one
// checked writer (OutputSet) whole.

#include <ImfIO.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace octaclay::core::detail {

class ExrMemoryStream : public Imf::OStream {
public:
  ExrMemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + n > bytes_.size()) bytes_.resize(position_ + n);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

private:
  std::vector<std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

} // namespace octaclay::core::detail
