#include "surface_samples.h"

#include <algorithm>
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
    std::vector<Vec3> pieces;
    std::vector<double> area;           // of each piece
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
          cell.pieces.push_back(cs[m]);
          cell.area.push_back(area);
          cell.triangle.push_back(t);
        }
      }
    }
  }
  std::vector<Vec3> normals(mesh.triangles.size());
  for (std::size_t t = 0; t < normals.size(); ++t)
    normals[t] = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).normalized();
  const auto normal_of = [&](std::size_t t) -> const Vec3& { return normals[t]; };
  SurfaceSamples s;
  std::vector<std::vector<std::size_t>> groups;  // of a cube's pieces, still to split or emit
  std::vector<std::size_t> directions;           // pieces of a group with distinct normals
  for (const auto& entry : cells) {
    const Cell& cell = entry.second;  // not a structured binding: clang 14's lambdas cannot capture one
    // A wall thinner than the cube puts both its faces in it: one sample would stand for the
    // other face's area at this face's temperature. While a group of the cube's pieces holds
    // faces turned more than 120 degrees from each other it is split in two: each piece goes
    // with the face its normal is nearer, or where it is turned from both alike (the rim of an
    // edge), with the one it lies on the side of. An edge of a thin wall holds four faces: two
    // splits. Each group left is a sample at its own centre with its own area.
    groups.assign(1, std::vector<std::size_t>(cell.pieces.size()));
    std::iota(groups[0].begin(), groups[0].end(), std::size_t(0));
    while (!groups.empty()) {
      const std::vector<std::size_t> group = std::move(groups.back());
      groups.pop_back();
      directions.clear();
      for (const std::size_t i : group)
        if (std::none_of(directions.begin(), directions.end(), [&](std::size_t j) {
              return normal_of(cell.triangle[i]).dot(normal_of(cell.triangle[j])) > 0.999;
            }))
          directions.push_back(i);
      std::size_t a = 0, b = 0;
      double opposed = -0.5;
      for (std::size_t i = 0; i < directions.size(); ++i)
        for (std::size_t j = i + 1; j < directions.size(); ++j)
          if (const double d = normal_of(cell.triangle[directions[i]]).dot(normal_of(cell.triangle[directions[j]]));
              d < opposed)
            opposed = d, a = directions[i], b = directions[j];
      if (a != b) {
        const Vec3 across = (normal_of(cell.triangle[a]) - normal_of(cell.triangle[b])).normalized();
        // Between the two faces: the midpoint of the centres of the pieces turned to either.
        Vec3 centre[2] = {Vec3::Zero(), Vec3::Zero()};
        double area[2] = {0, 0};
        for (const std::size_t i : group)
          if (const double turned = normal_of(cell.triangle[i]).dot(across); std::abs(turned) >= 0.5)
            centre[turned > 0 ? 0 : 1] += cell.area[i] * cell.pieces[i], area[turned > 0 ? 0 : 1] += cell.area[i];
        const Vec3 middle = 0.5 * (centre[0] / area[0] + centre[1] / area[1]);
        std::vector<std::size_t> halves[2];
        for (const std::size_t i : group) {
          const double turned = normal_of(cell.triangle[i]).dot(across);
          halves[(std::abs(turned) >= 0.5 ? turned : (cell.pieces[i] - middle).dot(across)) >= 0 ? 0 : 1].push_back(i);
        }
        groups.push_back(std::move(halves[0]));  // both hold a piece (a's, b's): each split shrinks
        groups.push_back(std::move(halves[1]));
        continue;
      }
      Vec3 sum = Vec3::Zero();
      double weight = 0;
      for (const std::size_t i : group) sum += cell.area[i] * cell.pieces[i], weight += cell.area[i];
      if (weight <= 0) continue;
      const Vec3 mean = sum / weight;
      std::size_t best = group.front();
      for (const std::size_t i : group)
        if ((cell.pieces[i] - mean).squaredNorm() < (cell.pieces[best] - mean).squaredNorm()) best = i;
      push(s, cell.pieces[best], weight, normal_of(cell.triangle[best]));
    }
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
