#pragma once

// Helpers shared by the core and CLI tests that check files: the atomic writer's temporaries and
// the .ocz container's trailing CRC-32.

#include <QDir>
#include <QStringList>
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octaclay::testing {

/// The atomic writer's temporaries (".name.tmp-PID-N.ext") left in folder.
inline QStringList temporaries(const QString& folder) {
  QStringList found;
  for (const QString& name : QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::System))
    if (name.contains(".tmp-")) found << name;
  return found;
}

/// Rewrites an .ocz file's trailing CRC-32 over its body, so a crafted header passes the check.
inline void resealCrc(std::vector<std::uint8_t>& bytes) {
  const std::size_t body = bytes.size() - 4;
  const auto crc = static_cast<std::uint32_t>(
      crc32(crc32(0L, Z_NULL, 0), bytes.data(), static_cast<uInt>(body)));
  for (int k = 0; k < 4; ++k)
    bytes[body + k] = std::uint8_t(crc >> (8 * k));
}

} // namespace octaclay::testing
