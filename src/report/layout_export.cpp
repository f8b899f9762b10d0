#include "mtcs/report/layout_export.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/shop_layout.h"
#include "mtcs/run/stored_run.h"
#include "mtcs/store/run_store.h"
#include "shop_member.h"
#include "step_writer.h"

namespace mtcs::report {
namespace {

using geometry::Vec3;

// The closed tube of a hole: two rings of kTubeSides points and a centre on each cap, outward.
mesh::TriangleMesh tube(const geometry::Cylinder& c) {
  const Vec3 w = (c.p1 - c.p0).normalized();
  const Vec3 u = w.unitOrthogonal(), v = w.cross(u);
  mesh::TriangleMesh m;
  const int n = kTubeSides;
  for (const Vec3& end : {c.p0, c.p1})
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      m.vertices.push_back(end + c.radius * (std::cos(a) * u + std::sin(a) * v));
    }
  m.vertices.push_back(c.p0);
  m.vertices.push_back(c.p1);
  const int c0 = 2 * n, c1 = 2 * n + 1;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
    m.triangles.push_back({c1, n + i, n + j});
    m.triangles.push_back({c0, j, i});
  }
  return m;
}

void write_vtp(std::ostream& out, const mold::Layout& layout) {
  std::vector<mesh::TriangleMesh> tubes;
  std::size_t points = 0, cells = 0;
  for (const auto& b : layout.bores) {
    tubes.push_back(tube(b.hole));
    points += tubes.back().vertices.size();
    cells += tubes.back().triangles.size();
  }
  out << std::setprecision(17) << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << points << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
      << cells << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& t : tubes)
    for (const auto& p : t.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  out << "</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  std::size_t base = 0;
  for (const auto& t : tubes) {
    for (const auto& tri : t.triangles) out << base + std::size_t(tri[0]) << ' ' << base + std::size_t(tri[1]) << ' ' << base + std::size_t(tri[2]) << '\n';
    base += t.vertices.size();
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 1; k <= cells; ++k) out << 3 * k << '\n';
  out << "</DataArray>\n</Polys>\n<CellData Scalars=\"circuit\">\n";
  auto cell_array = [&](const char* type, const char* name, auto value) {
    out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < layout.bores.size(); ++i)
      for (std::size_t k = 0; k < tubes[i].triangles.size(); ++k) out << value(i) << '\n';
    out << "</DataArray>\n";
  };
  cell_array("Int32", "circuit", [&](std::size_t i) { return layout.bores[i].circuit; });
  cell_array("Int32", "bore", [&](std::size_t i) { return i; });
  cell_array("Float64", "diameter", [&](std::size_t i) { return layout.bores[i].diameter; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

void write_obj(std::ostream& out, const mold::Layout& layout) {
  out << std::setprecision(17) << "# mtcs export: " << layout.bores.size() << " bores as closed " << kTubeSides
      << "-sided tubes, mm\n";
  std::size_t base = 1;  // OBJ counts vertices from 1
  for (const auto& b : layout.bores) {
    const mesh::TriangleMesh t = tube(b.hole);
    out << "o " << b.name() << "\n# circuit " << b.circuit << ", diameter " << b.diameter << " mm\n";
    for (const auto& p : t.vertices) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& tri : t.triangles)
      out << "f " << base + std::size_t(tri[0]) << ' ' << base + std::size_t(tri[1]) << ' ' << base + std::size_t(tri[2]) << '\n';
    base += t.vertices.size();
  }
}

}  // namespace

std::optional<ExportFormat> export_format(const std::string& name) {
  if (name == "step") return ExportFormat::Step;
  if (name == "vtp") return ExportFormat::Vtp;
  if (name == "obj") return ExportFormat::Obj;
  if (name == "csv") return ExportFormat::Csv;
  return std::nullopt;
}

void export_layout(const std::string& path, const mold::Layout& layout, ExportFormat format) {
  if (format == ExportFormat::Csv) return mold::save_bores_csv(path, layout);
  if (format == ExportFormat::Step) return write_step(path, layout);
  io::AtomicFile file(path);
  if (format == ExportFormat::Vtp) write_vtp(file.stream(), layout);
  else write_obj(file.stream(), layout);
  file.commit();
}

StoredLayout stored_layout(const std::string& run_dir, std::optional<int> generation, std::optional<int> member,
                           const std::string& mold_override) {
  const std::string db_path = (std::filesystem::path(run_dir) / "run.sqlite").string();
  if (!std::filesystem::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: no mold layout to export");
  StoredLayout s;
  const auto summaries = db.summaries();
  if (summaries.empty()) throw io::InputError(db_path, 0, 0, "generation", "the run stored no generation yet");
  s.generation = generation.value_or(summaries.back().index);
  const auto g = db.generation(s.generation);
  if (!g) throw io::InputError(db_path, 0, 0, "--generation", "no stored generation " + std::to_string(s.generation));
  if (member && (*member < 0 || std::size_t(*member) >= g->population.size()))
    throw io::InputError(db_path, 0, 0, "--member",
                         "generation " + std::to_string(s.generation) + " has members 0.." + std::to_string(g->population.size() - 1));
  // The best by the run's ranking (SMS-EMOA's need not be rank 0) without the thermal model:
  // the stored scores and a constraints-only session's problem rank it as the run did.
  const auto spec = run::stored_mold_spec(meta, mold_override, &s.note);
  s.session = std::make_unique<run::Session>(spec, meta.at("config"), db_path + ":config", eval::PipelineScope::constraints);
  const int best = int(run::best_rank(*g, s.session->problem()));
  s.member = member.value_or(best);
  // The last generation's best as optimize wrote it: polished, when it was. Only that one needs
  // the objectives (best.layout.yaml is taken when it scores what the run wrote); the shop's plan
  // needs the constraints alone (run::shop_layout keeps it feasible): no thermal model.
  const bool last_best = s.member == best && s.generation == summaries.back().index;
  if (last_best && was_polished(run_dir))
    s.session = std::make_unique<run::Session>(spec, meta.at("config"), db_path + ":config", eval::PipelineScope::everything);
  std::optional<ShopMember> polished;
  if (last_best) polished = polished_best(run_dir, *s.session, s.note);
  s.layout = polished ? polished->plan : shop_member(*s.session, g->population[std::size_t(s.member)].x).plan;
  return s;
}

StoredLayout layout_to_export(const std::string& source, const std::string& layout_file, std::optional<int> generation,
                              std::optional<int> member) {
  if (layout_file.empty()) return stored_layout(source, generation, member);
  StoredLayout s;  // the scene alone: decoding needs no pipeline (a thermal model can take seconds)
  const mold::Scene scene(mold::load_mold_spec(source));
  const mold::WrittenLayout written = mold::read_layout(layout_file, scene.spec());
  for (const mold::LayoutChange& c : written.changes) s.note += (s.note.empty() ? "" : "; ") + layout_file + ": " + c.what;
  s.layout = run::shop_plan(mold::decode(scene, written.genome));
  return s;
}

std::string default_export_path(const ExportRequest& r, const StoredLayout& s) {
  if (!r.layout_file.empty()) return std::filesystem::path(r.layout_file).replace_extension(r.format).string();
  return (std::filesystem::path(r.source) / "exports" /
          ("generation_" + std::to_string(s.generation) + "_member_" + std::to_string(s.member) + "." + r.format))
      .string();
}

Exported export_bores(const ExportRequest& r) {
  const auto format = export_format(r.format);
  if (!format) throw io::InputError("", 0, 0, "--format", "'" + r.format + "': give step, vtp, obj or csv");
  if (*format == ExportFormat::Step && !step_available()) throw io::InputError("", 0, 0, "--format", kStepMissing);
  StoredLayout s = layout_to_export(r.source, r.layout_file, r.generation, r.member);
  Exported e{r.out.empty() ? default_export_path(r, s) : r.out, s.note, s.layout.bores.size()};
  // A bare layout file name puts the export in the working folder: no folder to make.
  if (const auto folder = std::filesystem::path(e.path).parent_path(); r.out.empty() && !folder.empty())
    std::filesystem::create_directories(folder);
  export_layout(e.path, s.layout, *format);
  return e;
}

}  // namespace mtcs::report
