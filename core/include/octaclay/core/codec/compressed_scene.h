#pragma once

// The .ocz container of a scene (format version 2): every object's name, topology, image size,
// transform, visibility and lock, then each object's document as a version-1 container
// (compressed_document.h), then a CRC-32 of everything before it. Version-1 files (one document,
// written before scenes) read as one object.
//
// The codecs code square (N+1)² images on the octahedral ball's grid. A torus or plane object of
// W × H cells is coded on the square of side max(W, H), its last column and row repeated into the
// padding (the exact codecs' predictions make those rows nearly free), and cut back on reading.
// Only exact codecs may code such an object: a lossy codec seams its output as the ball's, which
// would tear a torus's period or move a plane's boundary.

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/scene.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// The container's format version for scenes; version 1 holds one document.
inline constexpr std::uint16_t kCompressedSceneVersion = 2;

/// Why options cannot code object, or nothing when they can: every codec codes every topology (a
/// torus or plane on a square, coded lossily one sample in from its seamed border on a square
/// twice its longer side, its wrap made exact again when decoded), but that square may not pass
/// the largest N.
std::optional<std::string> compressProblem(const SceneObject& object,
                                           const CompressOptions& options);

/// Whether the scene is what a version-1 file holds, its name aside: one octahedral object at the
/// identity, visible and unlocked. Writers keep today's format for it (writeCompressedModel).
bool isOneDocument(const Scene& scene);

/// The scene as .ocz bytes (version 2), every object coded with options. Throws
/// Error(InvalidArgument) for a scene sceneProblem refuses, an object compressProblem refuses, or
/// what compressDocument throws (an unknown codec, a quality out of range).
std::vector<std::uint8_t> compressScene(const Scene& scene, const CompressOptions& options);

/// The scene that bytes hold: version 2 as written by compressScene, version 1 as one object
/// named fallbackName at the identity, visible and unlocked. Throws Error(InvalidInput) naming
/// what is wrong (magic, version, checksum, an object count beyond kMaxSceneObjects or beyond
/// what the bytes can hold, a bad name, an unknown topology, sizes that are not a valid grid or
/// that disagree with the object's document, a transform transformProblem refuses, a flag other
/// than 0 or 1, lengths that disagree with the file, or what decompressDocument refuses), every
/// object's header checked before any image memory is taken.
Scene decompressScene(std::span<const std::uint8_t> bytes, std::string_view fallbackName = "Model");

/// Atomic write (writeBytesAtomically); errors as compressScene, and Error(Io).
void writeCompressedScene(const Scene& scene, const CompressOptions& options,
                          const std::filesystem::path& path);

/// Writes a version-1 file (writeCompressedDocument) when isOneDocument(scene), so every reader of
/// today opens it, else writeCompressedScene's version 2.
void writeCompressedModel(const Scene& scene, const CompressOptions& options,
                          const std::filesystem::path& path);

/// Reads a .ocz file of either version (a version-1 file's object named by the file's stem when
/// that is a valid object name, else "Model"). Error(Io) when it cannot be read; decompressScene's
/// errors prefixed with the path.
Scene readCompressedScene(const std::filesystem::path& path);

} // namespace octaclay::core
