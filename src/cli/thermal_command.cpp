// mtcs thermal: the cavity-surface temperature of one layout, by any tier: the summary, the heat
// balance, a field for ParaView / MeshLab or a picture, or temperatures at the user's points.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/cavity_temperature_report.h"
#include "mtcs/eval/thermal_problem_json.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/session.h"
#include "option_error.h"
#include "mtcs/report/python_plot.h"

namespace mtcs::cli {
namespace {

struct ThermalOptions {
  std::string mold, layout, tier, samples, out, problem;
  double cell = 0;
  int elements = 0;
  bool json = false;
};

}  // namespace

Command add_thermal_command(CLI::App& app) {
  auto opt = std::make_shared<ThermalOptions>();
  CLI::App* sub = app.add_subcommand(
      "thermal",
      "The cycle-averaged temperature of the cavity surface for one layout: mean, std and max\n"
      "(degC / K, area-weighted over the cavity samples), the hottest place, the heat balance (W), each circuit's coolant.\n"
      "Tiers: t1, t2, t2d (line sinks; M elements per bore), fd (finite volumes at a cell size, the\n"
      "reference; seconds per solve). Default: the spec's thermal.tier (docs/mold-spec.md).\n"
      "  --out field.vtp | field.ply | field.png   the temperature on the cavity surface (ParaView,\n"
      "                                            MeshLab, a picture)\n"
      "  --samples POINTS.csv --out T.csv          x,y,z,T at the points of a CSV with columns x,y,z\n"
      "Example: mtcs thermal molds/thermal_block.yaml --layout molds/thermal_block.layout.yaml --tier fd --cell 1");
  sub->add_option("mold", opt->mold, "mold spec (YAML)")->required();
  sub->add_option("--layout", opt->layout, "layout (YAML: circuits of waypoints)")->required();
  sub->add_option("--tier", opt->tier, "t1, t2, t2d or fd (default: the spec's)")->check(CLI::IsMember({"t1", "t2", "t2d", "fd"}));
  sub->add_option("--cell", opt->cell, "mm, the finite volumes' cell (default: the spec's cell_size)")->check(CLI::Range(0.1, 100.0));
  sub->add_option("--elements", opt->elements, "line-sink elements per bore (default: the spec's)")->check(CLI::Range(1, 64));
  CLI::Option* out = sub->add_option("--out", opt->out, "field.vtp, field.ply, field.png, or with --samples a CSV");
  sub->add_option("--samples", opt->samples, "CSV of points (columns x,y,z, mm): their temperatures go to --out")->needs(out);
  sub->add_option("--problem", opt->problem, "also the conduction problem as JSON, for a solver outside mtcs (SI films, mm)");
  sub->add_flag("--json", opt->json, "one JSON object on stdout: {tier, cavity_condition, mean, std, max, hottest, surface, samples, heat_in, heat_to_bores, heat_to_faces, cooling_time, cycle_time (s), ejectable, temperature_difference, seconds; sides with cavity.parting; coolant with a flow rate or supply pressure: per circuit flow, Reynolds, pressure drop (Pa), heat (W), rise (K), and the shop checks}");
  return {sub, [opt] {
            const std::string ext = std::filesystem::path(opt->out).extension().string();
            if (!opt->out.empty() && opt->samples.empty() && ext != ".vtp" && ext != ".ply" && ext != ".png")
              throw option_error("--out " + opt->out, "a field is written as .vtp, .ply or .png (or give --samples for a CSV)");
            // The scene alone: the temperatures below build their own model (not the pipeline's).
            const run::Session session(opt->mold, {}, eval::PipelineScope::constraints);
            const mold::Layout layout = mold::decode(session.scene(), session.read_layout(opt->layout));
            eval::ThermalQuery query = eval::thermal_query(session.spec());
            if (!opt->tier.empty()) query.tier = *mold::thermal_tier(opt->tier);  // CLI checked the name
            if (opt->cell > 0) query.cell = opt->cell;
            if (opt->elements > 0) query.elements = opt->elements;
            const bool fd = query.tier == mold::ThermalTier::Fd;
            if (opt->cell > 0 && !fd) std::cerr << "mtcs thermal: note: --cell is the finite volumes' (fd) cell: ignored by the line sinks\n";
            if (opt->elements > 0 && (fd || query.tier == mold::ThermalTier::T1))
              std::cerr << "mtcs thermal: note: --elements is t2/t2d's elements per bore: ignored by " << (fd ? "fd" : "t1") << "\n";
            const std::vector<geometry::Vec3> points =
                opt->samples.empty() ? std::vector<geometry::Vec3>{} : eval::read_steel_points(opt->samples, session.scene(), layout);
            // The field's vertices as far apart as the cavity's samples: the model resolves no
            // finer, and each vertex costs a sample's evaluation (the gear's: 34 600 of them).
            const double edge = opt->samples.empty() && !opt->out.empty() ? session.spec().cavity->sample_spacing : 0;
            const eval::CavityTemperature r = eval::cavity_temperature(session.scene(), layout, query, points, edge);
            if (!opt->problem.empty()) eval::write_thermal_problem_file(opt->problem, session.scene(), layout);

            if (!opt->samples.empty()) {
              io::AtomicFile file(opt->out);
              eval::write_point_temperatures_csv(file.stream(), points, r.at_points);
              file.commit();
              std::cerr << "mtcs thermal: " << points.size() << " temperatures to " << opt->out << "\n";
            } else if (!opt->out.empty()) {
              const bool png = ext == ".png";
              const std::string field_path = png ? opt->out + ".ply" : opt->out;
              io::AtomicFile file(field_path);
              eval::write_cavity_temperature_field(file.stream(), r, ext == ".vtp");
              file.commit();
              if (png) {
                const std::string title = "cavity temperature, tier " + r.tier;
                if (report::render_plot("plot_surface_field.py", {field_path, opt->out, title}, std::cerr)) std::filesystem::remove(field_path);
              }
              if (std::filesystem::exists(opt->out)) std::cerr << "mtcs thermal: the cavity-surface temperature to " << opt->out << "\n";
            }
            if (opt->json) eval::write_cavity_temperature_json(std::cout, r, std::cerr);
            else eval::write_cavity_temperature_text(std::cout, r);
            return 0;
          }};
}

}  // namespace mtcs::cli
