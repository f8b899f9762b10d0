#include "mtcs/eval/thermal_problem_json.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "mtcs/eval/thermal_model.h"
#include "mtcs/io/atomic_file.h"

namespace mtcs::eval {

namespace {

nlohmann::ordered_json point(const geometry::Vec3& p) { return {p.x(), p.y(), p.z()}; }

// W/(mm^2 K) to W/(m^2 K); infinite: null (Dirichlet).
nlohmann::ordered_json film(double per_mm2) {
  if (std::isinf(per_mm2)) return nullptr;
  return per_mm2 * 1e6;
}

}  // namespace

void write_thermal_problem_json(std::ostream& out, const thermal::Model& model, const thermal::Samples& samples) {
  const thermal::Setting& s = model.setting;
  static const char* const kFaces[] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (std::size_t f = 0; f < 6; ++f)
    faces.push_back({{"face", kFaces[f]}, {"film", film(s.faces[f].film)}, {"ambient", s.faces[f].ambient}});
  nlohmann::ordered_json triangles = nlohmann::ordered_json::array();
  for (const thermal::HeatedTriangle& t : s.heat_in)
    triangles.push_back({{"corners", {point(t.a), point(t.b), point(t.c)}},
                         {"flux", t.flux * 1e6},
                         {"film", film(t.film)},
                         {"part_temperature", t.part_temperature}});
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const thermal::Channel& c : model.channels) {
    nlohmann::ordered_json ch{{"p0", point(c.axis.p0)}, {"p1", point(c.axis.p1)}, {"radius", c.radius},
                              {"film", film(c.film)}, {"coolant", c.coolant}};
    // The warming coolant (thermal.coolant.rise): the circuit, the place in its flow order and
    // rho Q c_p (W/K); another solver warms each channel's coolant by the heat upstream over it.
    if (c.circuit >= 0 && c.capacity > 0)
      ch["circuit"] = c.circuit, ch["position"] = c.position, ch["capacity_W_K"] = c.capacity;
    channels.push_back(ch);
  }
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const geometry::Vec3& p : samples.points) points.push_back(point(p));
  const nlohmann::ordered_json j{
      {"units", {{"length", "mm"}, {"temperature", "degC"}, {"conductivity", "W/(m K)"}, {"film", "W/(m^2 K)"}, {"flux", "W/m^2"}}},
      {"block", {{"min", point(s.block.min)}, {"max", point(s.block.max)}}},
      {"conductivity", s.conductivity * 1e3},
      {"faces", faces},
      {"cavity_is_void", bool(s.cavity_box || s.cavity_mesh)},
      {"cavity", triangles},
      {"channels", channels},
      {"samples", points}};
  out << j.dump(1) << "\n";
}

void write_thermal_problem_file(const std::string& path, const mold::Scene& scene, const mold::Layout& layout) {
  io::AtomicFile file(path);
  write_thermal_problem_json(file.stream(), {thermal_setting(scene), thermal_channels(layout, scene.spec())},
                             thermal_samples(scene));
  file.commit();
}

}  // namespace mtcs::eval
