#include "surface_samples.h"

#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace mtcs::eval {

using geometry::Vec3;

double SurfaceSamples::total_weight() const { return std::accumulate(weight.begin(), weight.end(), 0.0); }

namespace {
void push(SurfaceSamples& s, const Vec3& p, double w, const Vec3& normal) {
  s.x.push_back(p.x()), s.y.push_back(p.y()), s.z.push_back(p.z()), s.weight.push_back(w);
  s.normal.push_back(normal);
}
}  // namespace

SurfaceSamples sample_box(const geometry::Box& box, double spacing) {
  SurfaceSamples s;
  const Vec3 size = box.size();
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const int ni = std::max(1, int(std::ceil(size[i] / spacing))), nj = std::max(1, int(std::ceil(size[j] / spacing)));
    const double di = size[i] / ni, dj = size[j] / nj;
    for (const double plane : {box.min[k], box.max[k]}) {
      Vec3 normal = Vec3::Zero();
      normal[k] = plane == box.max[k] && box.max[k] > box.min[k] ? 1 : -1;
      for (int a = 0; a < ni; ++a) {
        for (int b = 0; b < nj; ++b) {
          Vec3 p;
          p[k] = plane, p[i] = box.min[i] + (a + 0.5) * di, p[j] = box.min[j] + (b + 0.5) * dj;
          push(s, p, di * dj, normal);
        }
      }
    }
  }
  return s;
}

SurfaceSamples sample_mesh(const mesh::TriangleMesh& mesh, double spacing) {
  struct Cell {
    Vec3 sum = Vec3::Zero();
    double weight = 0;
    std::vector<Vec3> pieces;
    std::vector<std::size_t> triangle;  // of each piece
  };
  std::map<std::tuple<long, long, long>, Cell> cells;  // ordered: deterministic output
  const Vec3 origin = mesh.bounds().min;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int k = std::max(1, int(std::ceil(2 * longest / spacing)));
    const double area = 0.5 * (b - a).cross(c - a).norm() / (k * k);
    // k^2 sub-triangles: centroids of the upward and downward ones on a barycentric grid.
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k - i; ++j) {
        auto at = [&](double u, double v) { return a + (u / k) * (b - a) + (v / k) * (c - a); };
        std::array<Vec3, 2> cs{(at(i, j) + at(i + 1, j) + at(i, j + 1)) / 3, Vec3::Zero()};
        const int n = j + 1 < k - i ? 2 : 1;
        if (n == 2) cs[1] = (at(i + 1, j) + at(i + 1, j + 1) + at(i, j + 1)) / 3;
        for (int m = 0; m < n; ++m) {
          const Vec3 q = (cs[m] - origin) / spacing;
          Cell& cell = cells[{long(std::floor(q.x())), long(std::floor(q.y())), long(std::floor(q.z()))}];
          cell.sum += area * cs[m];
          cell.weight += area;
          cell.pieces.push_back(cs[m]);
          cell.triangle.push_back(t);
        }
      }
    }
  }
  SurfaceSamples s;
  for (const auto& [key, cell] : cells) {
    const Vec3 mean = cell.sum / cell.weight;
    std::size_t best = 0;
    for (std::size_t i = 1; i < cell.pieces.size(); ++i)
      if ((cell.pieces[i] - mean).squaredNorm() < (cell.pieces[best] - mean).squaredNorm()) best = i;
    const std::size_t t = cell.triangle[best];
    const Vec3 normal = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).normalized();
    push(s, cell.pieces[best], cell.weight, normal);
  }
  return s;
}

PatchAxes patch_axes(const geometry::Box& patch) {
  int k = 0;
  (patch.max - patch.min).minCoeff(&k);
  return k == 0 ? PatchAxes{1, 2, 0} : k == 1 ? PatchAxes{0, 2, 1} : PatchAxes{0, 1, 2};
}

SurfaceSamples sample_patch(const geometry::Box& patch, double spacing) {
  const auto [i, j, k] = patch_axes(patch);
  const Vec3 size = patch.size();
  const int ni = std::max(1, int(std::ceil(size[i] / spacing))), nj = std::max(1, int(std::ceil(size[j] / spacing)));
  const double di = size[i] / ni, dj = size[j] / nj;
  SurfaceSamples s;
  const Vec3 normal = Vec3::Zero();  // which side the melt is on is the patch's face's: not known here
  for (int b = 0; b < nj; ++b) {
    for (int a = 0; a < ni; ++a) {
      Vec3 p;
      p[k] = patch.min[k], p[i] = patch.min[i] + (a + 0.5) * di, p[j] = patch.min[j] + (b + 0.5) * dj;
      push(s, p, di * dj, normal);
    }
  }
  return s;
}

SurfaceSamples sample_cavity(const mold::Cavity& cavity) { return sample_cavity(cavity, cavity.sample_spacing); }

SurfaceSamples sample_cavity(const mold::Cavity& cavity, double spacing) {
  if (cavity.is_patch()) return sample_patch(*cavity.box, spacing);
  if (cavity.box) return sample_box(*cavity.box, spacing);
  return sample_mesh(cavity.mesh->mesh, spacing);
}

}  // namespace mtcs::eval
