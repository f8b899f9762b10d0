#include "mtcs/eval/cavity_temperature_report.h"

#include <iomanip>
#include <nlohmann/json.hpp>

namespace mtcs::eval {

void write_cavity_temperature_text(std::ostream& out, const CavityTemperature& r) {
  const std::size_t samples = r.at_samples.size();
  const auto& s = r.summary;
  out << std::fixed << std::setprecision(3) << "cavity temperature (tier " << r.tier << ", " << samples
      << " samples of the " << r.surface << " surface, area-weighted)\n"
      << "  mean " << s.mean << " degC, std " << s.std << " K, max " << s.max << " degC at ("
      << std::setprecision(1) << r.hottest.x() << ", " << r.hottest.y() << ", " << r.hottest.z() << ") mm\n"
      << std::setprecision(3) << "heat balance\n  in " << r.balance.in << " W = bores "
      << r.balance.to_channels << " W + outer faces " << r.balance.to_faces << " W (residual "
      << std::scientific << std::setprecision(1) << r.balance.residual() << " W)\n"
      << std::fixed << std::setprecision(3) << "seconds " << r.seconds << "\n";
}

void write_cavity_temperature_json(std::ostream& out, const CavityTemperature& r) {
  const nlohmann::ordered_json j{{"tier", r.tier},
                                 {"mean", r.summary.mean},
                                 {"std", r.summary.std},
                                 {"max", r.summary.max},
                                 {"hottest", {r.hottest.x(), r.hottest.y(), r.hottest.z()}},
                                 {"surface", r.surface},
                                 {"samples", r.at_samples.size()},
                                 {"heat_in", r.balance.in},
                                 {"heat_to_bores", r.balance.to_channels},
                                 {"heat_to_faces", r.balance.to_faces},
                                 {"seconds", r.seconds}};
  out << j.dump(2) << "\n";
}

void write_point_temperatures_csv(std::ostream& out, const std::vector<geometry::Vec3>& points,
                                  const std::vector<double>& temperatures) {
  out << "x,y,z,T\n" << std::setprecision(17);
  for (std::size_t i = 0; i < points.size(); ++i)
    out << points[i].x() << ',' << points[i].y() << ',' << points[i].z() << ',' << temperatures[i] << '\n';
}

}  // namespace mtcs::eval
