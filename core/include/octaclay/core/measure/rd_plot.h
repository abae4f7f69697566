#pragma once

// The rate–distortion plot of the compression report: two panels side by side, bits per
// vertex (log scale) against geometric PSNR and against the mean normal-angle error, one
// coloured curve per codec (Draco's as the reference).

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {

struct RdPlotPoint {
  double bitsPerVertex = 0;
  double psnr = 0;           ///< dB; not drawn in the PSNR panel when not finite (exact)
  double normalAngleDeg = 0; ///< mean, degrees; not drawn in its panel when 0 (exact)
};

struct RdSeries {
  std::string label;
  std::vector<RdPlotPoint> points; ///< joined in the order given
};

/// Draws the plot (about 1600×700 pixels) and writes it as PNG, atomically. Throws
/// Error(InvalidArgument) when no series has a drawable point, Error(Io) when it cannot write.
void writeRdPlot(std::span<const RdSeries> series, const std::string& title,
                 const std::filesystem::path& png);

class OutputSet;

/// writeRdPlot's file staged into `set` (atomic_output.h), committed with the caller's others.
void stageRdPlot(std::span<const RdSeries> series, const std::string& title,
                 const std::filesystem::path& png, OutputSet& set);

} // namespace octaclay::core
