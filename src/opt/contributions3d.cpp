// All exclusive contributions in 3-D in one sweep along z, O(n log n), every volume a sum of
// positive box terms (the idea of Guerreiro & Fonseca's HVC3D: each point's exclusive region in
// the current 2-D slice kept as boxes that open and close as the sweep goes).
//
// At height z the slice is the 2-D projection of the points seen so far. A point p on its
// staircase (non-dominated in 2-D) owns the rectangle R(p) = [p.x, X) x [p.y, Y) between its
// staircase neighbours (X: next point's x, Y: previous point's y). Its exclusive region is R(p)
// minus what the points dominated by p alone cover: their own staircase S(p) inside R(p). That
// region splits into vertical strips, one per element e of {p} + S(p): x in [e.x, next e.x or X),
// y in [p.y, e.y, or Y for p itself). A strip's volume accrues while the sweep rises; when its
// extent is about to change, it is closed (area x height so far, added to p's contribution) and
// reopened at the current z.
//
// A point dominated in 2-D by two distinct points never matters again (whatever comes later
// dominates it twice too) and is dropped. Every point enters the staircase, a secondary
// staircase, or neither once and leaves at most once: O(n log n) with balanced trees.

#include "contributions3d.h"

#include <array>
#include <cstddef>
#include <iterator>
#include <map>
#include <memory_resource>

namespace mtcs::opt::detail {
namespace {

struct Secondary {
  double y;
  double z0;  // when the strip starting at this point last opened
};

struct Owner {
  std::size_t index;  // into the caller's points
  double y;
  double z0;                               // p's own strip
  std::pmr::map<double, Secondary> secondary;  // S(p) by x: x increasing, y decreasing
};

class Sweep {
 public:
  Sweep(const Point& ref, double scale, std::vector<double>& out) : ref_(ref), scale_(scale), out_(out) {}
  Sweep(const Sweep&) = delete;
  Sweep& operator=(const Sweep&) = delete;

  void add(std::size_t index, double x, double y, double z) {
    auto after = stair_.upper_bound(x);  // first owner with x' > x
    if (after != stair_.begin()) {
      auto s = std::prev(after);  // last owner with x' <= x
      if (s->second.y <= y) {
        // Dominated by s: inside R(s) it trims p's exclusive region; above R(s) it is also
        // dominated by the previous owner and changes nothing.
        if (y < top(s)) add_secondary(s, x, y, z);
        return;
      }
    }
    add_owner(index, x, y, z);
  }

  void finish() {
    for (auto it = stair_.begin(); it != stair_.end(); ++it) close_all(it, ref_[2]);
    stair_.clear();
  }

 private:
  using Stair = std::pmr::map<double, Owner>;
  using It = Stair::iterator;
  using SecIt = std::pmr::map<double, Secondary>::iterator;

  double top(It it) const { return it == stair_.begin() ? ref_[1] : std::prev(it)->second.y; }
  double right(It it) const { return std::next(it) == stair_.end() ? ref_[0] : std::next(it)->first; }

  void accrue(It it, double width, double height, double& z0, double z) {
    out_[it->second.index] += scale_ * (width * height * (z - z0));
    z0 = z;
  }
  // p's own strip [p.x, first secondary x or X) x [p.y, Y).
  void close_own(It it, double z) {
    Owner& o = it->second;
    const double end = o.secondary.empty() ? right(it) : o.secondary.begin()->first;
    accrue(it, end - it->first, top(it) - o.y, o.z0, z);
  }
  void close_strip(It it, SecIt s, double z) {
    const double end = std::next(s) == it->second.secondary.end() ? right(it) : std::next(s)->first;
    accrue(it, end - s->first, s->second.y - it->second.y, s->second.z0, z);
  }
  // Closes the strip that ends where the element at x would start (x > p.x).
  void close_left_of(It it, SecIt first_at_or_after, double z) {
    auto& sec = it->second.secondary;
    if (first_at_or_after == sec.begin()) close_own(it, z);
    else close_strip(it, std::prev(first_at_or_after), z);
  }
  void close_all(It it, double z) {
    close_own(it, z);
    auto& sec = it->second.secondary;
    for (auto s = sec.begin(); s != sec.end(); ++s) close_strip(it, s, z);
  }

  void add_secondary(It owner, double x, double y, double z) {
    auto& sec = owner->second.secondary;
    auto after = sec.upper_bound(x);
    if (after != sec.begin() && std::prev(after)->second.y <= y) return;  // dominated twice
    auto first = sec.lower_bound(x);
    auto last = first;
    while (last != sec.end() && last->second.y >= y) ++last;  // the ones it dominates
    close_left_of(owner, first, z);
    for (auto s = first; s != last; ++s) close_strip(owner, s, z);
    sec.erase(first, last);
    sec.emplace_hint(last, x, Secondary{y, z});
  }

  void add_owner(std::size_t index, double x, double y, double z) {
    auto first = stair_.lower_bound(x);  // owners it dominates start here
    auto last = first;
    while (last != stair_.end() && last->second.y >= y) ++last;
    // The left neighbour's rectangle now ends at x: its strips from x on are closed, and the
    // points it dominated there are now dominated by the new point too.
    if (first != stair_.begin()) {
      const It left = std::prev(first);
      auto& sec = left->second.secondary;
      const auto cut = sec.lower_bound(x);
      close_left_of(left, cut, z);
      for (auto s = cut; s != sec.end(); ++s) close_strip(left, s, z);
      sec.erase(cut, sec.end());
    }
    // The right neighbour's rectangle now tops out at y: its own strip closes, and its
    // secondaries at or above y are dominated twice.
    if (last != stair_.end()) {
      auto& sec = last->second.secondary;
      auto keep = sec.begin();
      while (keep != sec.end() && keep->second.y >= y) ++keep;
      close_own(last, z);
      for (auto s = sec.begin(); s != keep; ++s) close_strip(last, s, z);
      sec.erase(sec.begin(), keep);
    }
    // The owners it dominates stop contributing and become its secondary staircase; what they
    // dominated is now dominated twice.
    Owner owner{index, y, z, std::pmr::map<double, Secondary>(&pool_)};
    for (auto it = first; it != last; ++it) {
      close_all(it, z);
      owner.secondary.emplace_hint(owner.secondary.end(), it->first, Secondary{it->second.y, z});
    }
    stair_.erase(first, last);
    stair_.emplace_hint(last, x, std::move(owner));
  }

  const Point& ref_;
  double scale_;
  std::vector<double>& out_;
  // Tree nodes from one arena, freed with the sweep: the sweep is mostly allocation otherwise.
  std::array<std::byte, 8192> buffer_;
  std::pmr::monotonic_buffer_resource pool_{buffer_.data(), buffer_.size()};
  Stair stair_{&pool_};
};

}  // namespace

void contributions3(const std::vector<Point>& points, const std::vector<std::size_t>& members, const Point& ref,
                    double scale, std::vector<double>& out) {
  Sweep sweep(ref, scale, out);
  for (const std::size_t i : members) sweep.add(i, points[i][0], points[i][1], points[i][2]);
  sweep.finish();
}

}  // namespace mtcs::opt::detail
