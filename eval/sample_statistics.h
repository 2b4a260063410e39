#pragma once

#include <span>
#include <vector>

namespace lrsvo {

// Sample moments: mean, standard deviation (divided by n), skewness and excess
// kurtosis (0 for a Gaussian). NaN for an empty sample (and the shape for a constant one).
struct Moments {
  double mean = 0.0;
  double stddev = 0.0;
  double skewness = 0.0;
  double excessKurtosis = 0.0;
};
Moments sampleMoments(std::span<const double> values);

// A sample sorted once, for order statistics. Throws lrsvo::Error when empty.
class SortedSample {
 public:
  explicit SortedSample(std::vector<double> values);

  std::size_t size() const { return values_.size(); }
  // Linear interpolation between order statistics, q in [0, 1].
  double quantile(double q) const;
  double median() const { return quantile(0.5); }
  // Bowley's quartile skewness (Q3 + Q1 - 2 Q2) / (Q3 - Q1), in [-1, 1]: a
  // shape measure that exists for heavy-tailed samples whose moments do not.
  double quartileSkewness() const;
  // The half-sample mode (Bickel and Fruehwirth 2006): repeatedly keep the
  // densest half of the sample (the shortest interval holding half the values).
  double halfSampleMode() const;

 private:
  std::vector<double> values_;
};

// Counts of values in `bins` equal bins over [low, high); values outside are
// counted in `below` and `above`.
struct Histogram {
  double low = 0.0;
  double high = 0.0;
  std::vector<long> counts;
  long below = 0;
  long above = 0;

  double binWidth() const { return (high - low) / static_cast<double>(counts.size()); }
  double binCentre(std::size_t bin) const { return low + (bin + 0.5) * binWidth(); }
};
Histogram makeHistogram(std::span<const double> values, double low, double high, int bins);

}  // namespace lrsvo
