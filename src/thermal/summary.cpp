#include <cmath>

#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

Summary summarize(const std::vector<double>& temperature, const Samples& samples) {
  Summary s;
  double total = 0, sum = 0;
  for (std::size_t i = 0; i < temperature.size(); ++i) {
    total += samples.weights[i];
    sum += samples.weights[i] * temperature[i];
    if (temperature[i] > temperature[s.hottest]) s.hottest = i;
  }
  if (temperature.empty() || total <= 0) return s;
  s.mean = sum / total;
  // Two passes: the spread is small next to the mean, so one-pass sums would cancel.
  double var = 0;
  for (std::size_t i = 0; i < temperature.size(); ++i) {
    const double d = temperature[i] - s.mean;
    var += samples.weights[i] * d * d;
  }
  s.std = std::sqrt(var / total);
  s.max = temperature[s.hottest];
  return s;
}

}  // namespace mtcs::thermal
