#include "mtcs/thermal/void_plane.h"

#include <array>
#include <cmath>

namespace mtcs::thermal {
namespace {

// The cavity box's face (2 k + side, side 1 = max) holding all three corners of t, or -1.
int face_of(const HeatedTriangle& t, const Box& box) {
  for (int k = 0; k < 3; ++k) {
    const double tol = 1e-9 * (1 + box.size().norm());
    for (int side = 0; side < 2; ++side) {
      const double plane = side ? box.max[k] : box.min[k];
      if (std::abs(t.a[k] - plane) <= tol && std::abs(t.b[k] - plane) <= tol && std::abs(t.c[k] - plane) <= tol)
        return 2 * k + side;
    }
  }
  return -1;
}

double heat(const HeatedTriangle& t) { return t.flux * 0.5 * (t.b - t.a).cross(t.c - t.a).norm(); }

}  // namespace

CavityCut cut_at_cavity_void(const Setting& setting) {
  if (!setting.cavity_box) return {setting};
  const Box& cavity = *setting.cavity_box;
  std::array<double, 6> face_heat{};
  double total = 0;
  for (const HeatedTriangle& t : setting.heat_in) {
    total += heat(t);
    if (const int f = face_of(t, cavity); f >= 0) face_heat[std::size_t(f)] += heat(t);
  }
  int cut = 0;
  for (int f = 1; f < 6; ++f)
    if (face_heat[std::size_t(f)] > face_heat[std::size_t(cut)]) cut = f;
  const int k = cut / 2, side = cut % 2;
  // The block beyond that face from the cavity: below a lower face, above an upper one.
  Setting out = setting;
  if (side == 0) out.block.max[k] = cavity.min[k];
  else out.block.min[k] = cavity.max[k];
  if (face_heat[std::size_t(cut)] <= 0 || !(out.block.max[k] > out.block.min[k])) return {setting};
  // The cut is the new block's face towards the cavity (its +k face below a lower face).
  out.faces[std::size_t(2 * k + (side == 0 ? 1 : 0))].film = 0;
  // The face's triangles carry every cavity face's heat (the rim's too: the heat balance holds).
  const double scale = total / face_heat[std::size_t(cut)];
  out.heat_in.clear();
  for (const HeatedTriangle& t : setting.heat_in)
    if (face_of(t, cavity) == cut) out.heat_in.push_back({t.a, t.b, t.c, t.flux * scale});
  out.cavity_box.reset();
  out.cavity_mesh.reset();
  return {out, k, side == 0 ? cavity.min[k] : cavity.max[k], side == 0};
}

double CavityCut::beyond(const Vec3& p) const { return keep_below ? p[axis] - plane : plane - p[axis]; }

bool CavityCut::splits(const Channel& ch) const {
  if (axis < 0) return false;
  const double h0 = beyond(ch.axis.p0), h1 = beyond(ch.axis.p1);
  return (h0 > 0) != (h1 > 0) && h0 != 0 && h1 != 0;
}

std::vector<Channel> CavityCut::fold(std::span<const Channel> channels) const {
  std::vector<Channel> out;
  if (axis < 0) return {channels.begin(), channels.end()};
  auto mirror = [&](Vec3 p) {
    if (beyond(p) > 0) p[axis] = 2 * plane - p[axis];
    return p;
  };
  for (const Channel& ch : channels) {
    if (!splits(ch)) {
      Channel c = ch;
      c.axis = {mirror(ch.axis.p0), mirror(ch.axis.p1)};
      out.push_back(c);
      continue;
    }
    const double h0 = beyond(ch.axis.p0), h1 = beyond(ch.axis.p1);
    const Vec3 x = ch.axis.p0 + (h0 / (h0 - h1)) * (ch.axis.p1 - ch.axis.p0);
    Channel a = ch, b = ch;
    a.axis = {mirror(ch.axis.p0), x};
    b.axis = {x, mirror(ch.axis.p1)};
    b.position += 0.5;  // downstream of a, upstream of the circuit's next bore (positions: segments, whole)
    out.push_back(a), out.push_back(b);
  }
  return out;
}

std::vector<double> CavityCut::unfold_heat(std::span<const Channel> channels, std::span<const double> folded_heat) const {
  std::vector<double> heat(channels.size(), 0.0);
  std::size_t k = 0;
  for (std::size_t i = 0; i < channels.size() && k < folded_heat.size(); ++i) {
    heat[i] = folded_heat[k++];
    if (splits(channels[i]) && k < folded_heat.size()) heat[i] += folded_heat[k++];
  }
  return heat;
}

}  // namespace mtcs::thermal
