#include "mtcs/run/run_record.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/run/session.h"
#include "mtcs/version.h"

namespace mtcs::run {
namespace {

namespace fs = std::filesystem;

// Every mesh file the spec loads, by path relative to the spec's folder.
std::vector<std::pair<std::string, std::string>> mesh_files(const mold::MoldSpec& spec) {
  std::vector<const mold::MeshSource*> sources;
  if (spec.block.mesh) sources.push_back(&*spec.block.mesh);
  if (spec.cavity && spec.cavity->mesh) sources.push_back(&*spec.cavity->mesh);
  for (const auto& k : spec.keep_outs)
    if (k.mesh) sources.push_back(&*k.mesh);
  const fs::path folder = fs::absolute(spec.path).parent_path();
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto* s : sources) out.emplace_back(fs::relative(fs::absolute(s->path), folder).string(), s->path);
  return out;
}

// "name<TAB>hash" lines, one per mesh file.
std::string mesh_hashes(const mold::MoldSpec& spec) {
  std::string out;
  for (const auto& [name, path] : mesh_files(spec)) out += name + '\t' + content_hash(read_file_text(path)) + '\n';
  return out;
}

std::map<std::string, std::string> parse_mesh_hashes(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (const auto tab = line.find('\t'); tab != std::string::npos) out[line.substr(0, tab)] = line.substr(tab + 1);
  return out;
}

}  // namespace

std::string content_hash(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string read_file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw io::InputError(path, 0, 0, "", "cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

RunMeta mold_run_meta(const std::string& mold_path, const Session& session) {
  const std::string text = read_file_text(mold_path);
  std::string objectives;
  for (const auto& n : session.objective_names()) objectives += (objectives.empty() ? "" : ",") + n;
  return {{"mold", fs::absolute(mold_path).string()},
          {"mold_hash", content_hash(text)},
          {"mold_text", text},
          {"mesh_hashes", mesh_hashes(session.spec())},
          {"config", session.config().to_yaml(session.objective_names())},
          {"seed", std::to_string(session.config().es.seed)},
          {"objectives", objectives},
          {"program", kProgram}};
}

std::string start_text(const std::vector<opt::Genotype>& start) {
  std::string out;
  char buf[32];
  for (const opt::Genotype& g : start) {
    for (std::size_t i = 0; i < g.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g", g[i]);
      out += (i ? " " : "") + std::string(buf);
    }
    out += '\n';
  }
  return out;
}

std::vector<opt::Genotype> stored_start(const RunMeta& meta, const std::string& origin) {
  std::vector<opt::Genotype> start;
  const auto it = meta.find("start");
  if (it == meta.end()) return start;
  std::istringstream lines(it->second);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream in(line);
    opt::Genotype g;
    std::string word;
    while (in >> word) {
      char* end = nullptr;
      g.push_back(std::strtod(word.c_str(), &end));
      if (end != word.c_str() + word.size() || !std::isfinite(g.back()))
        throw io::InputError(origin, number, 0, "start", "not a number in the stored start layout: " + word);
    }
    if (g.empty()) throw io::InputError(origin, number, 0, "start", "an empty stored start layout");
    start.push_back(std::move(g));
  }
  return start;
}

std::string MoldCheck::describe() const {
  std::string s;
  if (spec_changed) s = "the spec text";
  for (const auto& m : meshes_changed) s += (s.empty() ? "mesh " : ", mesh ") + m;
  return s.empty() ? "nothing" : s;
}

MoldCheck check_mold(const RunMeta& meta, const std::string& mold_path, const mold::MoldSpec& loaded) {
  MoldCheck c;
  c.spec_changed = content_hash(read_file_text(mold_path)) != meta.at("mold_hash");
  if (!meta.count("mesh_hashes")) return c;  // a run stored before meshes were hashed
  const auto stored = parse_mesh_hashes(meta.at("mesh_hashes"));
  const auto now = parse_mesh_hashes(mesh_hashes(loaded));
  for (const auto& [name, hash] : now)
    if (!stored.count(name) || stored.at(name) != hash) c.meshes_changed.push_back(name);
  for (const auto& [name, hash] : stored)
    if (!now.count(name)) c.meshes_changed.push_back(name);
  return c;
}

mold::MoldSpec stored_mold_spec(const RunMeta& meta, const std::string& override_path, std::string* note) {
  const std::string stored_path = meta.at("mold");
  // The spec at `path`; the note says whether it is the run's (silent on a match if `quiet`).
  auto checked = [&](const std::string& path, bool quiet) {
    mold::MoldSpec spec = mold::load_mold_spec(path);
    const MoldCheck c = check_mold(meta, path, spec);
    if (c.same()) *note = quiet ? "" : "mold " + path + ": the same spec and meshes as the run's";
    else
      *note = "mold " + path + " differs from the run's mold (" + c.describe() + "): objectives may not match the stored ones";
    return spec;
  };
  if (!override_path.empty()) return checked(override_path, false);
  if (fs::exists(stored_path)) return checked(stored_path, true);
  const bool has_text = meta.count("mold_text") > 0;
  const bool has_meshes = !meta.count("mesh_hashes") || !meta.at("mesh_hashes").empty();
  if (!has_text || has_meshes)
    throw io::InputError(stored_path, 0, 0, "mold",
                         "the run's mold is gone (moved or deleted)" + std::string(has_text ? " and loads mesh files" : "") +
                             ": give its new place with --mold");
  // The run's own spec: written where load_mold_spec can read it.
  const fs::path tmp =
      fs::temp_directory_path() / ("mtcs-replay-" + content_hash(stored_path + meta.at("mold_hash")) + ".yaml");
  {
    io::AtomicFile f(tmp.string());
    f.stream() << meta.at("mold_text");
    f.commit();
  }
  mold::MoldSpec spec = mold::load_mold_spec(tmp.string());
  fs::remove(tmp);
  spec.path = stored_path;
  *note = "mold " + stored_path + " is gone (moved or deleted): replayed with the spec text stored in the run";
  return spec;
}

}  // namespace mtcs::run
