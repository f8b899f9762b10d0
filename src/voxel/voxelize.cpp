// Exact voxelisation by signed ray crossings along x with symbolic perturbation.
//
// For a column of centres (y, z), the ray starts at the perturbed point (y + e, z + e^2) for an
// infinitesimal e > 0: it misses every vertex and edge of the projection onto the yz plane, so a
// triangle is crossed iff the perturbed point lies strictly inside its projection, and the
// winding number of a centre off the surface is the signed count of crossings beyond it (sign =
// sign of the triangle normal's x). Where the crossing lies relative to a centre is the exact
// orient3d sign; a centre on a triangle (orient3d 0 inside the closed projection, or inside a
// triangle parallel to x) is on the surface and not strictly inside.

#include <algorithm>
#include <cmath>

#include "mtcs/mesh/exact_predicates.h"
#include "mtcs/voxel/voxel_grid.h"

namespace mtcs::voxel {
namespace {

using mesh::orient2d;
using mesh::orient3d;

// Sign of orient2d(p, r, q) in the (u, v) plane for q moved by (e, e^2): the first non-zero
// term of the expansion in e.
int perturbed_side(double pu, double pv, double ru, double rv, double qu, double qv) {
  const int s = orient2d(pu, pv, ru, rv, qu, qv);
  if (s != 0) return s;
  if (rv != pv) return pv > rv ? 1 : -1;
  return ru > pu ? 1 : (ru < pu ? -1 : 0);
}

// Index of the last centre at or below x along `axis` (approximately: callers widen by one and
// let the exact tests decide), clamped to [-1, size].
int index_below(const GridSpec& g, int axis, double x) {
  const double t = std::floor((x - g.origin[axis]) / g.voxel_size - 0.5);
  if (!(t >= -1)) return -1;  // also NaN
  return t > g.size[axis] ? g.size[axis] : int(t);
}

}  // namespace

std::size_t VoxelGrid::count() const {
  return std::size_t(std::count(solid.begin(), solid.end(), std::uint8_t(1)));
}

Box VoxelGrid::voxel_box(int i, int j, int k) const {
  const double h = spec.voxel_size;
  const Vec3 lo(spec.origin.x() + i * h, spec.origin.y() + j * h, spec.origin.z() + k * h);
  return {lo, Vec3(spec.origin.x() + (i + 1) * h, spec.origin.y() + (j + 1) * h, spec.origin.z() + (k + 1) * h)};
}

VoxelGrid voxelize(const mesh::TriangleMesh& mesh, const GridSpec& spec) {
  const int nx = spec.size[0], ny = spec.size[1], nz = spec.size[2];
  VoxelGrid grid{spec, std::vector<std::uint8_t>(std::size_t(nx) * ny * nz, 0)};
  if (nx <= 0 || ny <= 0 || nz <= 0) return grid;
  // Per column: crossing contributions as a difference array over x (nx + 1 entries), and the
  // centres found on the surface.
  std::vector<int> diff(std::size_t(nx + 1) * ny * nz, 0);
  std::vector<std::uint8_t> on_surface(grid.solid.size(), 0);
  const auto column = [&](int j, int k) { return std::size_t(k) * ny + std::size_t(j); };
  std::array<Vec3, 3> v;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) v[std::size_t(c)] = mesh.corner(t, c);
    const Vec3 lo = v[0].cwiseMin(v[1]).cwiseMin(v[2]), hi = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
    // Columns whose centre may lie in the closed yz bounds (one extra each side: exact tests decide).
    const int j0 = std::max(0, index_below(spec, 1, lo.y())), j1 = std::min(ny - 1, index_below(spec, 1, hi.y()) + 1);
    const int k0 = std::max(0, index_below(spec, 2, lo.z())), k1 = std::min(nz - 1, index_below(spec, 2, hi.z()) + 1);
    const int s = orient2d(v[0].y(), v[0].z(), v[1].y(), v[1].z(), v[2].y(), v[2].z());
    for (int k = k0; k <= k1; ++k) {
      const double qz = spec.centre(2, k);
      for (int j = j0; j <= j1; ++j) {
        const double qy = spec.centre(1, j);
        int e[3], pe[3];
        for (int c = 0; c < 3; ++c) {
          const Vec3 &p = v[std::size_t(c)], &r = v[std::size_t((c + 1) % 3)];
          e[c] = orient2d(p.y(), p.z(), r.y(), r.z(), qy, qz);
          pe[c] = s != 0 && e[c] == 0 ? perturbed_side(p.y(), p.z(), r.y(), r.z(), qy, qz) : e[c];
        }
        if (s != 0) {
          // Closed projection must contain (qy, qz) for the line to meet the triangle at all.
          bool closed = true;
          for (int c = 0; c < 3; ++c) closed = closed && (e[c] == 0 || e[c] == s);
          if (!closed) continue;
          // Centres before the crossing have orient3d == -s; binary search along x.
          int a = 0, b = nx;
          while (a < b) {
            const int m = (a + b) / 2;
            const Vec3 q(spec.centre(0, m), qy, qz);
            if (orient3d(v[0], v[1], v[2], q) == -s) a = m + 1;
            else b = m;
          }
          if (a < nx && orient3d(v[0], v[1], v[2], Vec3(spec.centre(0, a), qy, qz)) == 0)
            on_surface[grid.index(a, j, k)] = 1;
          if (pe[0] == s && pe[1] == s && pe[2] == s) {
            int* d = &diff[column(j, k) * std::size_t(nx + 1)];
            d[0] += s;
            d[a] -= s;
          }
        } else {
          // A triangle parallel to x: only centres lying on it matter. The line meets its
          // plane only if (qy, qz) lies on the projected segment.
          if (e[0] != 0 || e[1] != 0 || e[2] != 0) continue;
          if (std::min({v[0].y(), v[1].y(), v[2].y()}) > qy || std::max({v[0].y(), v[1].y(), v[2].y()}) < qy) continue;
          if (std::min({v[0].z(), v[1].z(), v[2].z()}) > qz || std::max({v[0].z(), v[1].z(), v[2].z()}) < qz) continue;
          // In the plane, test containment in the xy or the xz projection, whichever is not flat.
          int axis = 1;
          int s2 = orient2d(v[0].x(), v[0].y(), v[1].x(), v[1].y(), v[2].x(), v[2].y());
          if (s2 == 0) {
            axis = 2;
            s2 = orient2d(v[0].x(), v[0].z(), v[1].x(), v[1].z(), v[2].x(), v[2].z());
          }
          if (s2 == 0) continue;  // degenerate triangle
          const double qw = axis == 1 ? qy : qz;
          const int i0 = std::max(0, index_below(spec, 0, lo.x())), i1 = std::min(nx - 1, index_below(spec, 0, hi.x()) + 1);
          for (int i = i0; i <= i1; ++i) {
            const double qx = spec.centre(0, i);
            bool inside = true;
            for (int c = 0; c < 3 && inside; ++c) {
              const Vec3 &p = v[std::size_t(c)], &r = v[std::size_t((c + 1) % 3)];
              const int o = orient2d(p.x(), p[axis], r.x(), r[axis], qx, qw);
              inside = o == 0 || o == s2;
            }
            if (inside) on_surface[grid.index(i, j, k)] = 1;
          }
        }
      }
    }
  }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const int* d = &diff[column(j, k) * std::size_t(nx + 1)];
      int winding = 0;
      for (int i = 0; i < nx; ++i) {
        winding += d[i];
        const std::size_t idx = grid.index(i, j, k);
        grid.solid[idx] = winding != 0 && !on_surface[idx];
      }
    }
  return grid;
}

}  // namespace mtcs::voxel
