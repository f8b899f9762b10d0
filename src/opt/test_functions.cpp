#include "test_functions.h"

#include <cmath>
#include <stdexcept>

namespace mtcs::opt {
namespace {

class TestFunction final : public Problem {
 public:
  TestFunction(std::string name, int n, bool correlated) : name_(std::move(name)), n_(n), correlated_(correlated) {}
  std::string name() const override { return name_; }
  std::size_t step_sizes(const Genotype& g) const override { return g.size(); }
  Genotype sample(Rng& rng) const override {
    Genotype x(static_cast<std::size_t>(n_));
    for (double& v : x) v = -5 + 10 * rng.uniform();
    return x;
  }
  // Correlated mutations (Schwefel 1995): n step sizes and n(n-1)/2 rotation angles.
  std::size_t rotation_angles(const Genotype& g) const override {
    return correlated_ ? g.size() * (g.size() - 1) / 2 : 0;
  }
  std::vector<double> initial_steps(const Genotype& g) const override {
    std::vector<double> s(g.size(), 1.0);
    s.resize(g.size() + rotation_angles(g), 0.0);
    return s;
  }
  long mutate(Genotype& g, const std::vector<double>& steps, Rng& rng) const override {
    const std::size_t n = g.size();
    std::vector<double> z(n);
    for (std::size_t k = 0; k < n; ++k) z[k] = steps[k] * rng.normal();
    // Rotate the uncorrelated move by the angles, one coordinate plane at a time.
    std::size_t a = n;
    for (std::size_t p = 0; correlated_ && p + 1 < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q, ++a) {
        const double c = std::cos(steps[a]), s = std::sin(steps[a]);
        const double zp = z[p] * c - z[q] * s, zq = z[p] * s + z[q] * c;
        z[p] = zp, z[q] = zq;
      }
    }
    for (std::size_t k = 0; k < n; ++k) g[k] += z[k];
    return 0;
  }
  // Intermediate recombination.
  Genotype recombine(const Genotype& a, const Genotype& b, Rng&) const override {
    Genotype c(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) c[k] = (a[k] + b[k]) / 2;
    return c;
  }
  Score evaluate(const Genotype& x) const override {
    double f = 0;
    const std::size_t n = x.size();
    if (name_ == "sphere") {
      for (const double v : x) f += v * v;
    } else if (name_ == "ellipsoid") {
      for (std::size_t k = 0; k < n; ++k) f += std::pow(1e6, n > 1 ? double(k) / double(n - 1) : 0.0) * x[k] * x[k];
    } else {
      for (std::size_t k = 0; k + 1 < n; ++k)
        f += 100 * std::pow(x[k + 1] - x[k] * x[k], 2) + std::pow(1 - x[k], 2);
    }
    return {{f}, 0, true, f, {}};
  }

 private:
  std::string name_;
  int n_;
  bool correlated_;
};

}  // namespace

std::unique_ptr<Problem> make_test_function(const std::string& name, int dimension, bool correlated) {
  if (name != "sphere" && name != "ellipsoid" && name != "rosenbrock")
    throw std::invalid_argument("unknown test function '" + name + "'");
  return std::make_unique<TestFunction>(name, dimension, correlated);
}

}  // namespace mtcs::opt
