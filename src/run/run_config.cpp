#include "mtcs/run/run_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "mtcs/io/yaml_reader.h"

namespace mtcs::run {

RunConfig parse_run_config(const std::string& text, const std::string& origin,
                           const std::vector<std::string>& objective_names) {
  const io::YamlReader r(origin);
  const YAML::Node root = io::parse_yaml(text, origin);
  RunConfig c;
  if (root.IsNull()) return c;
  r.expect_map(root, "", {"algorithm", "es", "evaluations", "seed", "weights", "mutation", "log_every", "ref", "penalty",
                          "fidelity"});
  if (root["algorithm"]) {
    c.algorithm = r.text(root["algorithm"], "algorithm");
    if (c.algorithm != "es" && c.algorithm != "sms-emoa") r.fail(root["algorithm"], "algorithm", "expected es or sms-emoa");
  }
  if (root["ref"]) {
    r.expect_sequence(root["ref"], "ref");
    for (std::size_t i = 0; i < root["ref"].size(); ++i)
      c.ref.push_back(r.number(root["ref"][i], io::indexed("ref", i), 1e-12, 1e12));
    if (c.ref.size() != objective_names.size())
      r.fail(root["ref"], "ref", "needs one value per objective (" + std::to_string(objective_names.size()) + ")");
  }
  if (root["es"]) {
    const YAML::Node& es = root["es"];
    r.expect_map(es, "es", {"mu", "lambda", "rho", "plus", "recombination", "restart_after", "restart", "restart_tolerance"});
    if (es["mu"]) c.es.mu = r.integer(es["mu"], "es.mu", 1, 100000);
    if (es["lambda"]) c.es.lambda = r.integer(es["lambda"], "es.lambda", 1, 1000000);
    if (es["rho"]) c.es.rho = r.integer(es["rho"], "es.rho", 1, 2);
    if (es["plus"]) c.es.plus = r.boolean(es["plus"], "es.plus");
    if (es["recombination"]) c.es.recombination = r.boolean(es["recombination"], "es.recombination");
    if (!c.es.plus && c.es.lambda < c.es.mu) r.fail(es, "es.lambda", "a comma strategy needs lambda >= mu");
    if (es["restart_after"]) c.es.restart_after = r.integer(es["restart_after"], "es.restart_after", 0, 1000000000);
    if (es["restart_tolerance"])
      c.es.restart_tolerance = r.number(es["restart_tolerance"], "es.restart_tolerance", 0, 1);
    if (es["restart"]) {
      const std::string mode = r.text(es["restart"], "es.restart");
      if (mode == "steps") c.es.restart = opt::EsConfig::Restart::steps;
      else if (mode == "population") c.es.restart = opt::EsConfig::Restart::population;
      else r.fail(es["restart"], "es.restart", "must be steps or population, not '" + mode + "'");
    }
  }
  if (root["evaluations"]) c.es.evaluations = r.integer(root["evaluations"], "evaluations", 1, 2000000000);
  if (root["seed"]) c.es.seed = std::uint64_t(r.number(root["seed"], "seed", 0, 9.007199254740992e15));
  if (root["penalty"]) {
    c.penalty = mold::penalty_variant(r.text(root["penalty"], "penalty"));
    if (!c.penalty) r.fail(root["penalty"], "penalty", "expected one of " + mold::kPenaltyVariantNames);
  }
  if (root["log_every"]) c.log_every = r.integer(root["log_every"], "log_every", 1, 1000000);
  if (root["weights"]) {
    const YAML::Node& w = root["weights"];
    if (!w.IsMap()) r.fail(w, "weights", "expected a mapping objective: weight");
    c.weights.assign(objective_names.size(), 1.0);
    for (auto it = w.begin(); it != w.end(); ++it) {
      const std::string key = it->first.Scalar();
      const auto pos = std::find(objective_names.begin(), objective_names.end(), key);
      if (pos == objective_names.end()) r.fail(it->first, "weights." + key, "not an objective of this mold");
      c.weights[std::size_t(pos - objective_names.begin())] = r.number(it->second, "weights." + key, 0, 1e12);
    }
  }
  if (root["fidelity"]) {
    const YAML::Node& f = root["fidelity"];
    r.expect_map(f, "fidelity", {"screen", "elements_per_bore", "wall_images", "sample_spacing", "survivors", "final_cell"});
    if (f["screen"]) {
      const std::string s = r.text(f["screen"], "fidelity.screen");
      if (s == "t1") c.screen_tier = mold::ThermalTier::T1;
      else if (s == "t2") c.screen_tier = mold::ThermalTier::T2;
      else if (s == "t2d") c.screen_tier = mold::ThermalTier::T2d;
      else r.fail(f["screen"], "fidelity.screen", "expected t1, t2 or t2d (a line-sink tier); got '" + s + "'");
    }
    if (f["elements_per_bore"]) c.screen_elements = r.integer(f["elements_per_bore"], "fidelity.elements_per_bore", 1, 1000);
    if (f["wall_images"]) c.screen_wall_images = r.integer(f["wall_images"], "fidelity.wall_images", 1, 3);
    if (f["sample_spacing"]) c.screen_sample_spacing = r.number(f["sample_spacing"], "fidelity.sample_spacing", 1e-3, 1e6);
    for (const char* key : {"wall_images", "sample_spacing"})
      if (f[key] && !f["screen"]) r.fail(f[key], std::string("fidelity.") + key, "needs fidelity.screen");
    c.es.survivors = c.screen_tier ? c.es.mu : 0;
    if (f["survivors"]) {
      if (!c.screen_tier) r.fail(f["survivors"], "fidelity.survivors", "needs fidelity.screen");
      c.es.survivors = r.integer(f["survivors"], "fidelity.survivors", 1, c.es.lambda);
    }
    if (!c.es.plus && c.es.survivors > 0 && c.es.survivors < c.es.mu)
      r.fail(f, "fidelity.survivors", "a comma strategy needs survivors >= es.mu");
    if (f["final_cell"]) c.final_cell = r.number(f["final_cell"], "fidelity.final_cell", 0, 100);
  }
  if (root["mutation"]) {
    const YAML::Node& m = root["mutation"];
    r.expect_map(m, "mutation",
                 {"insert", "remove", "snap", "diameter", "circuit", "access_guided", "moves", "blend", "reach", "jog", "baffle"});
    if (m["insert"]) c.mutation.insert = r.number(m["insert"], "mutation.insert", 0, 1);
    if (m["remove"]) c.mutation.remove = r.number(m["remove"], "mutation.remove", 0, 1);
    if (m["snap"]) c.mutation.snap = r.number(m["snap"], "mutation.snap", 0, 1);
    if (m["diameter"]) c.mutation.diameter = r.number(m["diameter"], "mutation.diameter", 0, 1);
    if (m["circuit"]) c.mutation.circuit = r.number(m["circuit"], "mutation.circuit", 0, 1);
    if (m["access_guided"]) c.mutation.access_guided = r.boolean(m["access_guided"], "mutation.access_guided");
    if (m["moves"]) c.mutation.moves = r.number(m["moves"], "mutation.moves", 0, 1000);
    if (m["blend"]) c.mutation.blend = r.number(m["blend"], "mutation.blend", 0, 1);
    if (m["reach"]) c.mutation.reach = r.number(m["reach"], "mutation.reach", 0, 1);
    if (m["jog"]) c.mutation.jog = r.number(m["jog"], "mutation.jog", 0, 1);
    if (m["baffle"]) c.mutation.baffle = r.number(m["baffle"], "mutation.baffle", 0, 1);
  }
  return c;
}

RunConfig parse_stored_run_config(const std::string& text, const std::string& origin,
                                  const std::vector<std::string>& objective_names) {
  RunConfig c = parse_run_config(text, origin, objective_names);
  const YAML::Node root = YAML::Load(text);  // parsed above, so it loads
  if (!root.IsMap() || !root["es"] || !root["es"]["restart_after"]) c.es.restart_after = 0;
  // Runs stored before the jog move (or with it off) resume without it.
  if (!root.IsMap() || !root["mutation"] || !root["mutation"]["jog"]) c.mutation.jog = 0;
  return c;
}

RunConfig load_run_config(const std::string& path, const std::vector<std::string>& objective_names) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path, 0, 0, "", "cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_run_config(ss.str(), path, objective_names);
}

std::string RunConfig::to_yaml(const std::vector<std::string>& objective_names) const {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "algorithm" << YAML::Value << algorithm;
  if (!ref.empty()) {
    out << YAML::Key << "ref" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const double v : ref) out << v;
    out << YAML::EndSeq;
  }
  out << YAML::Key << "es" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "mu" << YAML::Value << es.mu
      << YAML::Key << "lambda" << YAML::Value << es.lambda << YAML::Key << "rho" << YAML::Value << es.rho << YAML::Key
      << "plus" << YAML::Value << es.plus << YAML::Key << "recombination" << YAML::Value << es.recombination
      << YAML::Key << "restart_after" << YAML::Value << es.restart_after << YAML::Key << "restart" << YAML::Value
      << (es.restart == opt::EsConfig::Restart::population ? "population" : "steps") << YAML::Key
      << "restart_tolerance" << YAML::Value << es.restart_tolerance << YAML::EndMap;
  out << YAML::Key << "evaluations" << YAML::Value << es.evaluations;
  out << YAML::Key << "seed" << YAML::Value << es.seed;
  out << YAML::Key << "log_every" << YAML::Value << log_every;
  if (penalty) out << YAML::Key << "penalty" << YAML::Value << mold::to_string(*penalty);
  if (screen_tier || final_cell > 0) {
    out << YAML::Key << "fidelity" << YAML::Value << YAML::Flow << YAML::BeginMap;
    if (screen_tier)
      out << YAML::Key << "screen" << YAML::Value << mold::to_string(*screen_tier) << YAML::Key << "survivors"
          << YAML::Value << es.survivors;
    if (screen_elements > 0) out << YAML::Key << "elements_per_bore" << YAML::Value << screen_elements;
    if (screen_wall_images > 0) out << YAML::Key << "wall_images" << YAML::Value << screen_wall_images;
    if (screen_sample_spacing) out << YAML::Key << "sample_spacing" << YAML::Value << *screen_sample_spacing;
    if (final_cell > 0) out << YAML::Key << "final_cell" << YAML::Value << final_cell;
    out << YAML::EndMap;
  }
  if (!weights.empty()) {
    out << YAML::Key << "weights" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (std::size_t k = 0; k < weights.size() && k < objective_names.size(); ++k)
      out << YAML::Key << objective_names[k] << YAML::Value << weights[k];
    out << YAML::EndMap;
  }
  out << YAML::Key << "mutation" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "insert" << YAML::Value
      << mutation.insert << YAML::Key << "remove" << YAML::Value << mutation.remove << YAML::Key << "snap"
      << YAML::Value << mutation.snap << YAML::Key << "diameter" << YAML::Value << mutation.diameter << YAML::Key
      << "circuit" << YAML::Value << mutation.circuit << YAML::Key << "access_guided" << YAML::Value
      << mutation.access_guided << YAML::Key << "moves" << YAML::Value << mutation.moves << YAML::Key << "reach"
      << YAML::Value << mutation.reach;
  if (mutation.blend > 0) out << YAML::Key << "blend" << YAML::Value << mutation.blend;  // older runs' configs stay as they were
  if (mutation.jog > 0) out << YAML::Key << "jog" << YAML::Value << mutation.jog;
  if (mutation.baffle != MutationRates{}.baffle) out << YAML::Key << "baffle" << YAML::Value << mutation.baffle;
  out << YAML::EndMap;
  out << YAML::EndMap;
  std::string s = out.c_str();
  return s + "\n";
}

}  // namespace mtcs::run
