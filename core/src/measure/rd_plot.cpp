#include "octaclay/core/measure/rd_plot.h"

#include "detail/png_codec.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <vector>

namespace octaclay::core {
namespace {

constexpr int kPanelWidth = 800, kHeight = 700;
constexpr int kLeft = 90, kRight = 20, kTop = 60, kBottom = 70;
const cv::Scalar kInk(40, 40, 40), kGrid(225, 225, 225), kWhite(255, 255, 255);

// A colour per series, distinct on white (BGR).
cv::Scalar seriesColour(std::size_t k) {
  static const cv::Scalar palette[] = {
      {0, 0, 0},      {200, 90, 30},  {40, 150, 40}, {30, 30, 210}, {170, 60, 170},
      {20, 140, 220}, {140, 140, 20}, {90, 90, 160}, {100, 60, 20}, {60, 170, 170}};
  return palette[k % std::size(palette)];
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void extend(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
  // Widen a degenerate or tight range so every point sits inside the frame.
  void pad(double fraction, double minimum) {
    const double span = std::max(hi - lo, minimum);
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * span * (1 + 2 * fraction);
    hi = mid + 0.5 * span * (1 + 2 * fraction);
  }
};

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, std::abs(v) >= 100 || v == std::floor(v) ? "%.0f" : "%.3g", v);
  return text;
}

// One panel: x = log2(bits per vertex), y = value(point) (already transformed), with ticks.
struct Panel {
  cv::Mat canvas; // a view of the whole image's panel area
  Range x, y;
  bool logY = false;

  cv::Point at(double xv, double yv) const {
    const double w = canvas.cols - kLeft - kRight, h = canvas.rows - kTop - kBottom;
    const double px = kLeft + (xv - x.lo) / (x.hi - x.lo) * w;
    const double py = kTop + (1 - (yv - y.lo) / (y.hi - y.lo)) * h;
    return {static_cast<int>(std::lround(px)), static_cast<int>(std::lround(py))};
  }

  void drawFrame(const std::string& yLabel, const std::string& heading) {
    const int x0 = kLeft, x1 = canvas.cols - kRight, y0 = kTop, y1 = canvas.rows - kBottom;
    for (int e = static_cast<int>(std::ceil(x.lo)); e <= static_cast<int>(std::floor(x.hi)); ++e) {
      const cv::Point p = at(e, y.lo);
      cv::line(canvas, {p.x, y0}, {p.x, y1}, kGrid, 1);
      cv::putText(canvas, format(std::exp2(e)), {p.x - 12, y1 + 22}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                  kInk, 1, cv::LINE_AA);
    }
    const double step = logY ? 1.0 : niceStep(y.hi - y.lo);
    for (double v = std::ceil(y.lo / step) * step; v <= y.hi; v += step) {
      const cv::Point p = at(x.lo, v);
      cv::line(canvas, {x0, p.y}, {x1, p.y}, kGrid, 1);
      cv::putText(canvas, format(logY ? std::pow(10.0, v) : v), {8, p.y + 5},
                  cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk, 1, cv::LINE_AA);
    }
    cv::rectangle(canvas, {x0, y0}, {x1, y1}, kInk, 1);
    cv::putText(canvas, "bits per vertex (log scale)", {x0 + (x1 - x0) / 2 - 110, y1 + 50},
                cv::FONT_HERSHEY_SIMPLEX, 0.6, kInk, 1, cv::LINE_AA);
    cv::putText(canvas, yLabel, {x0 + 8, y0 - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.55, kInk, 1,
                cv::LINE_AA);
    cv::putText(canvas, heading, {x0, 22}, cv::FONT_HERSHEY_SIMPLEX, 0.65, kInk, 1, cv::LINE_AA);
  }

  static double niceStep(double span) {
    const double raw = span / 8;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * magnitude >= raw) return m * magnitude;
    return 10 * magnitude;
  }
};

// Points of one series in panel coordinates, or none where the value is not drawable.
std::vector<std::array<double, 2>> panelPoints(const RdSeries& s, bool anglePanel) {
  std::vector<std::array<double, 2>> out;
  for (const RdPlotPoint& p : s.points) {
    if (!(p.bitsPerVertex > 0) || !std::isfinite(p.bitsPerVertex)) continue;
    const double y = anglePanel ? p.normalAngleDeg : p.psnr;
    if (!std::isfinite(y) || (anglePanel && !(y > 0))) continue;
    out.push_back({std::log2(p.bitsPerVertex), anglePanel ? std::log10(y) : y});
  }
  return out;
}

void drawPanel(cv::Mat canvas, std::span<const RdSeries> series, bool anglePanel) {
  Panel panel{canvas, {}, {}, anglePanel};
  for (const RdSeries& s : series)
    for (const auto& p : panelPoints(s, anglePanel)) {
      panel.x.extend(p[0]);
      panel.y.extend(p[1]);
    }
  // Exact points (infinite PSNR) sit on the PSNR panel's top edge as triangles.
  std::vector<std::pair<std::size_t, double>> exact;
  if (!anglePanel)
    for (std::size_t k = 0; k < series.size(); ++k)
      for (const RdPlotPoint& p : series[k].points)
        if (std::isinf(p.psnr) && p.psnr > 0 && p.bitsPerVertex > 0 &&
            std::isfinite(p.bitsPerVertex)) {
          exact.emplace_back(k, std::log2(p.bitsPerVertex));
          panel.x.extend(exact.back().second);
        }
  if (panel.x.empty() || panel.y.empty()) {
    cv::putText(canvas, "no lossy points", {kLeft + 20, kHeight / 2}, cv::FONT_HERSHEY_SIMPLEX, 0.7,
                kInk, 1, cv::LINE_AA);
    return;
  }
  panel.x.pad(0.04, 1.0);
  panel.y.pad(0.04, anglePanel ? 1.0 : 5.0);
  panel.drawFrame(
      anglePanel ? "mean normal-angle error (degrees, log scale)" : "geometric PSNR (dB)",
      anglePanel ? "Bits per vertex vs. normal-angle error" : "Bits per vertex vs. PSNR");
  for (std::size_t k = 0; k < series.size(); ++k) {
    const auto points = panelPoints(series[k], anglePanel);
    const cv::Scalar colour = seriesColour(k);
    const int thickness = k == 0 ? 2 : 1;
    for (std::size_t p = 0; p < points.size(); ++p) {
      const cv::Point here = panel.at(points[p][0], points[p][1]);
      cv::circle(canvas, here, 4, colour, cv::FILLED, cv::LINE_AA);
      if (p > 0)
        cv::line(canvas, panel.at(points[p - 1][0], points[p - 1][1]), here, colour, thickness,
                 cv::LINE_AA);
    }
  }
  for (const auto& [k, x] : exact) {
    const cv::Point top = panel.at(x, panel.y.hi);
    const std::vector<cv::Point> triangle{
        {top.x, top.y + 2}, {top.x - 7, top.y + 14}, {top.x + 7, top.y + 14}};
    cv::fillConvexPoly(canvas, triangle, seriesColour(k), cv::LINE_AA);
  }
  if (!exact.empty())
    cv::putText(canvas, "exact (top edge)", {kLeft + 6, kTop + 30}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                kInk, 1, cv::LINE_AA);
  // Legend in the panel's lower right (PSNR) or upper right (angle), where curves thin out.
  int y = anglePanel ? kTop + 20 : kHeight - kBottom - 20 * static_cast<int>(series.size());
  for (std::size_t k = 0; k < series.size(); ++k, y += 20) {
    const int x = canvas.cols - kRight - 190;
    cv::line(canvas, {x, y - 5}, {x + 24, y - 5}, seriesColour(k), 2, cv::LINE_AA);
    cv::putText(canvas, series[k].label, {x + 30, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk, 1,
                cv::LINE_AA);
  }
}

} // namespace

void stageRdPlot(std::span<const RdSeries> series, const std::string& title,
                 const std::filesystem::path& png, OutputSet& set) {
  const bool drawable = std::any_of(series.begin(), series.end(), [](const RdSeries& s) {
    return !panelPoints(s, false).empty() || !panelPoints(s, true).empty();
  });
  if (!drawable) throw Error(ErrorKind::InvalidArgument, "rate-distortion plot: no point to draw");
  cv::Mat image(kHeight + 40, 2 * kPanelWidth, CV_8UC3, kWhite);
  cv::putText(image, title, {kLeft, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, kInk, 2, cv::LINE_AA);
  for (int k = 0; k < 2; ++k)
    drawPanel(image(cv::Rect(k * kPanelWidth, 40, kPanelWidth, kHeight)), series, k == 1);
  // OpenCV draws in BGR; libpng writes RGB.
  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  const std::span<const std::uint8_t> samples(rgb.ptr<std::uint8_t>(0), rgb.total() * 3);
  set.stageBytes(png, detail::encodePng(samples, rgb.cols, rgb.rows, 3));
}

void writeRdPlot(std::span<const RdSeries> series, const std::string& title,
                 const std::filesystem::path& png) {
  OutputSet set;
  stageRdPlot(series, title, png, set);
  set.commit();
}

} // namespace octaclay::core
