#include "lrsvo/eval/sample_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

Moments sampleMoments(std::span<const double> values) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (values.empty()) return {nan, nan, nan, nan};
  const double n = static_cast<double>(values.size());
  double sum = 0.0;
  for (double v : values) sum += v;
  const double mean = sum / n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : values) {
    const double d = v - mean;
    const double d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (!(m2 > 0.0)) return {mean, 0.0, nan, nan};
  return {mean, std::sqrt(m2), m3 / std::pow(m2, 1.5), m4 / (m2 * m2) - 3.0};
}

SortedSample::SortedSample(std::vector<double> values) : values_(std::move(values)) {
  if (values_.empty()) throw Error("sorted sample: no values");
  std::sort(values_.begin(), values_.end());
}

double SortedSample::quantile(double q) const {
  if (!(q >= 0.0 && q <= 1.0)) throw Error("quantile: q = " + std::to_string(q) + " is outside [0, 1]");
  const double position = q * static_cast<double>(values_.size() - 1);
  const std::size_t below = static_cast<std::size_t>(position);
  if (below + 1 >= values_.size()) return values_.back();
  const double fraction = position - static_cast<double>(below);
  return values_[below] + fraction * (values_[below + 1] - values_[below]);
}

double SortedSample::quartileSkewness() const {
  const double q1 = quantile(0.25), q2 = quantile(0.5), q3 = quantile(0.75);
  return q3 > q1 ? (q3 + q1 - 2.0 * q2) / (q3 - q1) : 0.0;
}

double SortedSample::halfSampleMode() const {
  std::size_t first = 0, count = values_.size();
  while (count > 3) {
    const std::size_t half = (count + 1) / 2;
    std::size_t best = first;
    double bestWidth = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i + half <= first + count; ++i) {
      const double width = values_[i + half - 1] - values_[i];
      if (width < bestWidth) {
        bestWidth = width;
        best = i;
      }
    }
    first = best;
    count = half;
  }
  const double* v = values_.data() + first;
  if (count == 3) {
    const double lower = v[1] - v[0], upper = v[2] - v[1];
    if (lower < upper) return 0.5 * (v[0] + v[1]);
    if (upper < lower) return 0.5 * (v[1] + v[2]);
    return v[1];
  }
  return count == 2 ? 0.5 * (v[0] + v[1]) : v[0];
}

Histogram makeHistogram(std::span<const double> values, double low, double high, int bins) {
  if (bins <= 0 || !(high > low))
    throw Error("histogram: needs bins > 0 and high > low, got " + std::to_string(bins) + " bins over [" +
                std::to_string(low) + ", " + std::to_string(high) + ")");
  Histogram histogram{low, high, std::vector<long>(bins, 0), 0, 0};
  const double scale = bins / (high - low);
  for (double v : values) {
    if (v < low) {
      ++histogram.below;
    } else if (v >= high) {
      ++histogram.above;
    } else {
      const auto bin = std::min(static_cast<std::size_t>((v - low) * scale), histogram.counts.size() - 1);
      ++histogram.counts[bin];
    }
  }
  return histogram;
}

}  // namespace lrsvo
