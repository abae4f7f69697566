// The wavelet encoder's step search: a bracketing search on the normal step, the tangential
// steps a fixed ratio of it.

#include "codec/wavelet_step_search.h"

#include "octaclay/core/codec/wavelet_codec.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <cmath>

namespace octaclay::core::detail {
namespace {

// The tangential steps are these many times the normal one, across and along the grid's i
// direction (quantizer frameAt): the rate minimum on armadillo at 95 dB (4 and 4 cost 1.5 %
// more); the tangential error stays well within kWaveletTangentFactor.
constexpr double kAcrossStepRatio = 4;
constexpr double kAlongStepRatio = 6;

// The errors the bound is stated for, over the vertices: positions along the original
// surface's normals and across them, other channels each alone.
struct Errors {
  double normal = 0, tangent = 0;
  std::vector<double> scalar;
};

class ErrorMeter {
public:
  ErrorMeter(const std::vector<std::vector<float>>& original, int n) : original_(original), n_(n) {
    if (original.size() < static_cast<std::size_t>(kVectorChannels)) return;
    GeometryImage image(n);
    auto texels = image.texels();
    for (std::size_t k = 0; k < texels.size(); ++k)
      texels[k] = {original[0][k], original[1][k], original[2][k], 0.0f};
    normals_ = computeNormals(image);
  }

  Errors measure(const std::vector<std::vector<float>>& rebuilt) const {
    const auto w = static_cast<std::size_t>(n_) + 1;
    const std::size_t channels = original_.size();
    const bool vector = !normals_.empty();
    Errors e;
    e.scalar.assign(channels, 0.0);
    std::size_t count = 0;
    forEachCanonicalRun(n_, [&](int j, int begin, int end) {
      for (int i = begin; i < end; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i);
        std::size_t c = 0;
        if (vector) {
          const Vec3f d{rebuilt[0][k] - original_[0][k], rebuilt[1][k] - original_[1][k],
                        rebuilt[2][k] - original_[2][k]};
          const double along = dot(d, normals_[k]);
          e.normal += along * along;
          e.tangent += std::max(0.0, static_cast<double>(dot(d, d)) - along * along);
          c = 3;
        }
        for (; c < channels; ++c) {
          const double d = static_cast<double>(rebuilt[c][k]) - original_[c][k];
          e.scalar[c] += d * d;
        }
      }
      count += static_cast<std::size_t>(end - begin);
    });
    const auto rms = [count](double sum) { return std::sqrt(sum / static_cast<double>(count)); };
    e.normal = rms(e.normal);
    e.tangent = rms(e.tangent);
    for (double& x : e.scalar)
      x = rms(x);
    return e;
  }

private:
  const std::vector<std::vector<float>>& original_;
  int n_;
  std::vector<Vec3f> normals_;
};

// How far the error is past the bound: ≤ 1 when every part is within it.
double excess(const Errors& e, double target) {
  double worst = std::max(e.normal / target, e.tangent / (kWaveletTangentFactor * target));
  for (double x : e.scalar)
    worst = std::max(worst, x / target);
  return worst;
}

void setSteps(std::vector<ChannelCoding>& coding, double step) {
  for (std::size_t c = 0; c < coding.size(); ++c)
    coding[c].step =
        static_cast<float>(c >= 1 && c < static_cast<std::size_t>(kVectorChannels) &&
                                   coding.size() >= static_cast<std::size_t>(kVectorChannels)
                               ? step * (c == 1 ? kAcrossStepRatio : kAlongStepRatio)
                               : step);
}

} // namespace

void chooseWaveletSteps(const std::vector<std::vector<float>>& original,
                        const std::vector<std::vector<float>>& coefficients,
                        std::vector<ChannelCoding>& coding, double target, CoefficientPlanes& q) {
  const ErrorMeter meter(original, q.n);
  std::vector<std::vector<float>> rebuilt;
  const auto excessAt = [&](double step) {
    setSteps(coding, step);
    rebuild(q, coding, rebuilt, &coefficients);
    return excess(meter.measure(rebuilt), target);
  };
  double good = 0, bad = 0;
  double step = target * 3.0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double over = excessAt(step);
    if (over <= 1) {
      good = step;
      if (bad == 0) {
        step *= std::clamp(1 / std::max(over, 1e-300), 1.1, 4.0);
        continue;
      }
    } else {
      bad = step;
      if (good == 0) {
        step *= std::clamp(1 / over, 0.25, 0.9);
        continue;
      }
    }
    if (bad / good < 1.02) break;
    step = std::sqrt(good * bad);
  }
  if (good == 0)
    throw Error(ErrorKind::InvalidArgument,
                "wavelet: the error bound cannot be met in float precision; use a larger one");
  excessAt(good);
}

} // namespace octaclay::core::detail
