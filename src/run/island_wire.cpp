#include "island_wire.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace mtcs::run::wire {
namespace {

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put(const std::vector<double>& v) {
    put(std::uint64_t(v.size()));
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  void put(const std::string& s) {
    put(std::uint64_t(s.size()));
    out += s;
  }
  void put(const std::vector<opt::Individual>& pop) {
    put(std::uint64_t(pop.size()));
    for (const auto& ind : pop) {
      put(ind.x), put(ind.steps), put(ind.score.objectives), put(ind.score.violation);
      put(std::uint8_t(ind.score.feasible)), put(ind.score.value), put(ind.score.detail);
    }
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : in_(bytes) {}
  template <class T>
  T get() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::vector<double> doubles() {
    std::vector<double> v(get<std::uint64_t>());
    take(v.data(), v.size() * sizeof(double));
    return v;
  }
  std::string text() {
    std::string s(get<std::uint64_t>(), '\0');
    take(s.data(), s.size());
    return s;
  }
  std::vector<opt::Individual> population() {
    std::vector<opt::Individual> pop(get<std::uint64_t>());
    for (auto& ind : pop) {
      ind.x = doubles(), ind.steps = doubles(), ind.score.objectives = doubles();
      ind.score.violation = get<double>(), ind.score.feasible = get<std::uint8_t>() != 0;
      ind.score.value = get<double>(), ind.score.detail = text();
    }
    return pop;
  }

 private:
  void take(void* to, std::size_t n) {
    if (n > in_.size() - at_) throw std::runtime_error("island message: truncated");
    if (n > 0) std::memcpy(to, in_.data() + at_, n);
    at_ += n;
  }
  const std::string& in_;
  std::size_t at_ = 0;
};

}  // namespace

std::string encode(const std::vector<opt::Individual>& individuals) {
  Writer w;
  w.put(individuals);
  return w.out;
}

std::vector<opt::Individual> decode_individuals(const std::string& bytes) { return Reader(bytes).population(); }

namespace {

void put(Writer& w, const opt::Generation& g) {
  w.put(std::int64_t(g.index)), w.put(std::int64_t(g.evaluations)), w.put(std::int64_t(g.stalled)), w.put(g.population);
}

opt::Generation get(Reader& r) {
  opt::Generation g;
  g.index = int(r.get<std::int64_t>());
  g.evaluations = long(r.get<std::int64_t>());
  g.stalled = int(r.get<std::int64_t>());
  g.population = r.population();
  return g;
}

}  // namespace

std::string encode(const opt::Generation& g) {
  Writer w;
  put(w, g);
  return w.out;
}

opt::Generation decode_generation(const std::string& bytes) {
  Reader r(bytes);
  return get(r);
}

std::string encode(const std::vector<opt::Generation>& generations) {
  Writer w;
  w.put(std::uint64_t(generations.size()));
  for (const auto& g : generations) put(w, g);
  return w.out;
}

std::vector<opt::Generation> decode_generations(const std::string& bytes) {
  Reader r(bytes);
  std::vector<opt::Generation> out(r.get<std::uint64_t>());
  for (auto& g : out) g = get(r);
  return out;
}

}  // namespace mtcs::run::wire
