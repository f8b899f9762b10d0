#include "mtcs/run/islands.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cpu_clock.h"
#include "island_writer.h"
#include "mtcs/io/input_error.h"
#include "mtcs/run/progress_line.h"

namespace mtcs::run {
namespace {

// One island: the run's optimiser with the island's seed and share of the budget.
class Island {
 public:
  Island(const MoldOptimizer& base, const opt::Problem& problem, int index, int islands)
      : es_(problem, config(base.es().config(), index, islands)),
        sms_(problem, config(base.sms().config(), index, islands)), pareto_(base.pareto()), mu_(base.mu()),
        alone_(islands == 1) {}

  opt::Generation initial() const { return pareto_ ? sms_.initial() : es_.initial(); }
  // The island's end. Alone, the plain run's. With others, where its budget ends for the
  // offspring alone: what mutations spend besides (the reach move's evaluations) differs from
  // island to island, and every island must end at the same meeting (on MPI each rank decides
  // alone).
  bool done(const opt::Generation& g) const {
    if (alone_) return pareto_ ? sms_.done(g) : es_.done(g);
    opt::Generation offspring_only;
    offspring_only.index = g.index;
    offspring_only.evaluations = pareto_ ? sms_.config().mu + long(g.index) * sms_.config().lambda
                                         : es_.config().mu + long(g.index) * es_.config().lambda;
    return pareto_ ? sms_.done(offspring_only) : es_.done(offspring_only);
  }
  // One stored generation on: an ES generation, or SMS-EMOA's steps to the next multiple of mu.
  opt::Generation advance(const opt::Generation& g) const {
    if (!pareto_) return es_.step(g);
    opt::Generation next = sms_.step(g);
    while (next.index % mu_ != 0 && !done(next)) next = sms_.step(next);
    return next;
  }
  // Whether the generation `g` ends with a migration.
  bool migrates_after(const opt::Generation& g, int every) const {
    if (done(g) || (pareto_ && g.index % mu_ != 0)) return false;
    const int n = pareto_ ? g.index / mu_ : g.index;
    return n > 0 && n % every == 0;
  }
  // The number of the migration at (or last before) the generation `g`: 1 for the first.
  int migration(const opt::Generation& g, int every) const { return (pareto_ ? g.index / mu_ : g.index) / every; }
  // The generation index of migration `j`.
  int migration_generation(int j, int every) const { return (pareto_ ? mu_ : 1) * j * every; }
  std::vector<opt::Individual> emigrants(const opt::Generation& g, int k) const {
    return pareto_ ? sms_.emigrants(g, k) : opt::best_emigrants(g, k);
  }
  opt::Generation immigrate(const opt::Generation& g, const std::vector<opt::Individual>& arrivals) const {
    if (arrivals.empty()) return g;
    return pareto_ ? sms_.immigrate(g, arrivals) : es_.immigrate(g, arrivals);
  }

 private:
  template <class Config>
  static Config config(Config c, int index, int islands) {
    c.seed = opt::island_seed(c.seed, index);
    c.evaluations /= islands;
    // With others, an island's share counts its offspring alone (done, above): its moves'
    // evaluations come on top, as the islands end together whatever each one's moves spent.
    c.moves_within_budget = islands == 1;
    return c;
  }
  opt::EvolutionStrategy es_;
  opt::SmsEmoa sms_;
  bool pareto_;
  int mu_;
  bool alone_;  // the only island: it ends where the plain run ends
};

// Every island's members in one generation (the archipelago's): ES best first (stable), SMS-EMOA
// in island order. `from` (if given) gets where each member comes from: its index among the
// islands' members in island order (the store keeps the archipelago as these references).
opt::Generation merge(const MoldOptimizer& base, const opt::Problem& problem, const std::vector<opt::Generation>& islands,
                      std::vector<int>* from = nullptr) {
  std::vector<const opt::Individual*> all;
  opt::Generation m;
  m.index = islands.front().index;
  for (const auto& g : islands) {
    m.evaluations += g.evaluations;
    for (const auto& ind : g.population) all.push_back(&ind);
  }
  std::vector<int> order(all.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = int(j);
  if (!base.pareto())
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return problem.better(all[std::size_t(a)]->score, all[std::size_t(b)]->score); });
  m.population.reserve(all.size());
  for (const int j : order) m.population.push_back(*all[std::size_t(j)]);
  if (from) *from = std::move(order);
  return m;
}

// The islands meet at least this often (stored generations), migrating or not: what rank 0 holds
// unstored, what a kill -9 loses and how long a stop waits stay small.
constexpr std::size_t kMaxStretch = 10;

// All islands in this process: each message is queued, and received from the queue in order.
class ThreadTransport final : public IslandTransport {
 public:
  std::vector<int> local(int islands) const override {
    std::vector<int> all(static_cast<std::size_t>(islands));
    for (int i = 0; i < islands; ++i) all[std::size_t(i)] = i;
    return all;
  }
  bool writer() const override { return true; }
  void send_migrants(const std::vector<std::vector<opt::Individual>>& outgoing, int islands,
                     opt::Topology topology) override {
    std::vector<std::vector<opt::Individual>> arrivals(static_cast<std::size_t>(islands));
    for (int i = 0; i < islands; ++i)
      for (const int s : opt::migration_sources(topology, islands, i))
        arrivals[std::size_t(i)].insert(arrivals[std::size_t(i)].end(), outgoing[std::size_t(s)].begin(),
                                        outgoing[std::size_t(s)].end());
    migrants_.push_back(std::move(arrivals));
  }
  std::vector<std::vector<opt::Individual>> receive_migrants(int, opt::Topology) override { return pop(migrants_); }
  void send_stretch(std::vector<std::vector<opt::Generation>> local, int) override { stretches_.push_back(std::move(local)); }
  std::vector<std::vector<opt::Generation>> receive_stretch(int) override { return pop(stretches_); }
  void send_stop(bool value) override { stops_.push_back(value); }
  bool receive_stop() override { return pop(stops_); }
  std::vector<std::vector<opt::Generation>> scatter(const std::vector<std::vector<opt::Generation>>& all, int) override {
    return all;
  }
  bool broadcast(bool value) override { return value; }
  std::string broadcast(const std::string& value) override { return value; }
  bool all(bool value) override { return value; }
  std::vector<std::string> gather_text(const std::string& local) override { return {local}; }

 private:
  template <class T>
  static T pop(std::deque<T>& queue) {
    if (queue.empty()) throw std::logic_error("islands: a message received before it was sent");
    T front = std::move(queue.front());
    queue.pop_front();
    return front;
  }
  std::deque<std::vector<std::vector<opt::Individual>>> migrants_;
  std::deque<std::vector<std::vector<opt::Generation>>> stretches_;
  std::deque<bool> stops_;
};

}  // namespace

std::unique_ptr<IslandTransport> thread_transport() { return std::make_unique<ThreadTransport>(); }

int mpi_launch_size() {
  // Open MPI's mpirun says so in the environment of every rank it starts (MPICH: PMI_SIZE).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 0;
}

int threads_per_rank() {
  if (mpi_launch_size() == 0) return 0;
  int local = 1;  // ranks on this machine (Open MPI; MPICH: MPI_LOCALNRANKS)
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(name)) {
      local = std::max(1, std::atoi(v));
      break;
    }
  return std::max(1, int(std::thread::hardware_concurrency()) / local);
}

std::string IslandSettings::to_text() const {
  return "islands: " + std::to_string(islands) + "\nmigration_every: " + std::to_string(migration_every) +
         "\nmigrants: " + std::to_string(migrants) + "\ntopology: " + opt::topology_name(topology) +
         "\nmigration_delay: " + std::to_string(migration_delay) + "\n";
}

IslandSettings IslandSettings::parse(const std::string& text, const std::string& origin) {
  IslandSettings s;
  s.migration_delay = 0;  // stores made before the delay existed migrated in lockstep
  std::istringstream in(text);
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    ++row;
    const auto colon = line.find(": ");
    if (colon == std::string::npos) continue;
    const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
    try {
      if (key == "islands") s.islands = std::stoi(value);
      else if (key == "migration_every") s.migration_every = std::stoi(value);
      else if (key == "migrants") s.migrants = std::stoi(value);
      else if (key == "migration_delay") s.migration_delay = std::stoi(value);
      else if (key == "topology") s.topology = opt::parse_topology(value);
    } catch (const std::exception& e) {
      throw io::InputError(origin, row, colon + 3, key, "not a valid value: " + value);
    }
  }
  if (s.islands < 1 || s.migration_every < 1 || s.migrants < 0 || s.migration_delay < 0)
    throw io::InputError(origin, 0, 0, "islands",
                         "needs islands >= 1, migration_every >= 1, migrants >= 0, migration_delay >= 0");
  return s;
}

std::string island_progress_line(const MoldOptimizer& base, const opt::Generation& merged,
                                 const std::vector<opt::Generation>& islands, double seconds, long evaluations) {
  std::string each;
  char buf[40];
  for (const auto& g : islands) {
    if (base.pareto()) std::snprintf(buf, sizeof buf, " %.4g", base.scaled_hypervolume(opt::SmsEmoa::front(g)));
    else std::snprintf(buf, sizeof buf, " %.4g", g.population.front().score.value);
    each += buf;
  }
  std::string line = progress_line(base, merged, seconds, evaluations);
  // SMS-EMOA's generation on the line counts steps of all islands' populations: say so by islands.
  return "islands " + std::to_string(islands.size()) + " | " + line + " | " + (base.pareto() ? "HV" : "best") + " by island" +
         each;
}

namespace {

// Where a process's wall time goes in run_islands, for the speed study (the --verbose log).
// Also the CPU seconds of this thread between two meetings of the islands (its work: with one
// thread a rank, what the rank would take on a core of its own), for experiments/islands/speedup.py.
struct Phases {
  double evaluate = 0, migrate = 0, gather = 0, store = 0, stop = 0;
  double end = 0;  // waiting at the end for the last meetings and migrants (the slowest island's finish)
  std::vector<double> work;
  double work_start = thread_cpu_seconds(), waiting_cpu = 0;
  void met() {
    const double now = thread_cpu_seconds();
    work.push_back(now - work_start - waiting_cpu);
    work_start = now, waiting_cpu = 0;
  }
  // A call to the other processes: its wall time into `into`, its CPU (polls) out of the work.
  template <class F>
  auto waited(double& into, F&& f) {
    struct Add {
      double& cpu;
      double t0 = thread_cpu_seconds();
      ~Add() { cpu += thread_cpu_seconds() - t0; }
    } add{waiting_cpu};
    return timed(into, std::forward<F>(f));
  }
  template <class F>
  static auto timed(double& into, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Add {
      double& into;
      std::chrono::steady_clock::time_point t0;
      ~Add() { into += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
    } add{into, t0};
    return f();
  }
};

}  // namespace

StoredRun run_islands(const MoldOptimizer& base, const MoldProblem& problem, const IslandSettings& s,
                      IslandTransport& transport, store::RunStore* db,
                      const std::function<void(int, const std::function<std::string()>&)>& on_line,
                      const std::function<bool()>& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_seconds();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const int P = s.islands, delay = s.migration_delay;
  const std::vector<int> mine = transport.local(P);
  std::vector<Island> islands;
  for (const int i : mine) islands.emplace_back(base, problem, i, P);

  // Where to start: the store's last generation of every island (the writer reads, the others
  // receive theirs), or fresh populations. Before it, each island's generations at the last
  // `delay` migrations: the migrants then sent have not arrived at the last generation, and are
  // sent again (chosen from the same stored generations, so the same members).
  double seconds_before = 0;
  long evals_before = 0;
  std::vector<std::vector<opt::Generation>> all;
  if (db) {
    if (const auto last = db->last()) {
      seconds_before = db->summaries().back().seconds;
      evals_before = last->evaluations;
      const Island& any = islands.front();
      const int sent = P > 1 ? any.migration(*last, s.migration_every) : 0;
      std::vector<int> indices;
      for (int j = std::max(1, sent - delay + 1); j <= sent && delay > 0; ++j)
        indices.push_back(any.migration_generation(j, s.migration_every));
      indices.push_back(last->index);
      for (int i = 0; i < P; ++i) {
        std::vector<opt::Generation> island;
        for (const int index : indices) {
          auto g = db->island_generation(i, index);
          if (!g) throw std::runtime_error("run store: island " + std::to_string(i) + " has no generation " +
                                           std::to_string(index) + " (not an island run of " + std::to_string(P) + ")");
          island.push_back(std::move(*g));
        }
        all.push_back(std::move(island));
      }
    }
  }
  const bool resuming = transport.broadcast(!all.empty());
  std::vector<opt::Generation> gens(islands.size());
  Phases phases;
  long migrations_sent = 0, migrations_received = 0;
  if (resuming) {
    std::vector<std::vector<opt::Generation>> stored = transport.scatter(all, P);
    for (std::size_t k = 0; k < islands.size(); ++k) {
      gens[k] = std::move(stored[k].back());
      stored[k].pop_back();
    }
    for (std::size_t j = 0; j < stored.front().size(); ++j) {
      std::vector<std::vector<opt::Individual>> out;
      for (std::size_t k = 0; k < islands.size(); ++k) out.push_back(islands[k].emigrants(stored[k][j], s.migrants));
      transport.send_migrants(out, P, s.topology);
      ++migrations_sent;
    }
  } else {
    Phases::timed(phases.evaluate, [&] {
      tbb::parallel_for(std::size_t(0), islands.size(), [&](std::size_t k) { gens[k] = islands[k].initial(); });
    });
  }
  long local_evals_before = 0;
  if (resuming)
    for (const auto& g : gens) local_evals_before += g.evaluations;

  // The writer's store, written from a thread of its own while the islands go on.
  // The archipelago's generation (all members, merged) is made there too, off the islands' path.
  std::optional<IslandWriter> writing;
  if (db)
    writing.emplace(*db, [&](store::IslandsGeneration& g) { g.merged = merge(base, problem, g.islands, &g.merged_from); });
  std::vector<opt::Generation> last;  // every island's last generation (the writer's)
  StoredRun r;
  // Each local island's generations since the last meeting, and the seconds at which the first
  // local island (island 0 at the writer) had each.
  std::vector<std::vector<opt::Generation>> stretch(islands.size());
  std::vector<double> stretch_seconds;
  // The writer's meetings whose generations it has not received yet: their seconds, and whether
  // the meeting is where a resumed run starts (stored already).
  struct Meeting {
    std::vector<double> seconds;
    bool resumed = false;
  };
  std::deque<Meeting> meetings;
  long meetings_sent = 0, meetings_received = 0;
  // The generations and the stop of the oldest meeting not received: the writer stores the
  // stretch of every island, generation by generation, and tells the live line (a resumed
  // meeting: takes its last generation as the run's). Returns whether to stop.
  auto receive_meeting = [&] {
    std::vector<std::vector<opt::Generation>> every =
        phases.waited(phases.gather, [&] { return transport.receive_stretch(P); });
    const bool stopping = phases.waited(phases.stop, [&] { return transport.receive_stop(); });
    ++meetings_received;
    if (!transport.writer()) return stopping;
    const Meeting meeting = std::move(meetings.front());
    meetings.pop_front();
    Phases::timed(phases.store, [&] {
      const std::size_t n = every.front().size();
      std::vector<store::IslandsGeneration> stored;
      for (const auto& island : every)
        if (island.size() != n) throw std::logic_error("islands: islands met at different generations");
      for (std::size_t k = 0; k < n; ++k) {
        store::IslandsGeneration gen;
        for (auto& island : every) gen.islands.push_back(std::move(island[k]));
        if (k + 1 == n) last = gen.islands;
        if (meeting.resumed) continue;
        const double sec = meeting.seconds[k];
        if (on_line)
          on_line(gen.islands.front().index, [&] {
            const opt::Generation merged = merge(base, problem, gen.islands);
            return island_progress_line(base, merged, gen.islands, sec, merged.evaluations - evals_before);
          });
        if (writing) {
          gen.seconds = seconds_before + sec;
          stored.push_back(std::move(gen));
        }
      }
      if (writing && !stored.empty()) writing->push(std::move(stored));
    });
    return stopping;
  };
  // At a meeting: this process's stretch goes to the writer, the writer's stop() to every process,
  // without waiting; then the meeting `delay` meetings ago is received (the writer stores it).
  // Returns whether to stop here: the writer's stop() of that meeting.
  auto meet = [&](bool resumed) {
    phases.waited(phases.gather, [&] { transport.send_stretch(std::move(stretch), P); });
    stretch.assign(islands.size(), {});
    transport.send_stop(transport.writer() && stop && stop());
    if (transport.writer()) meetings.push_back({std::move(stretch_seconds), resumed});
    stretch_seconds.clear();
    ++meetings_sent;
    const bool stopping = meetings_sent - meetings_received > delay && receive_meeting();
    phases.met();
    return stopping;
  };
  for (std::size_t k = 0; k < islands.size(); ++k) stretch[k].push_back(gens[k]);
  stretch_seconds.push_back(elapsed());
  bool stopping = meet(resuming);

  // Every island runs to the next meeting on its own (a migration, the end, or kMaxStretch
  // generations on); all islands step alike, so they meet at the same generation.
  auto runs_on = [&](std::size_t k) {
    const Island& island = islands[k];
    return !island.done(gens[k]) && !island.migrates_after(gens[k], s.migration_every) &&
           stretch[k].size() < kMaxStretch;
  };
  auto run_on = [&](std::size_t k, bool moves_messages) {
    do {
      gens[k] = islands[k].advance(gens[k]);
      stretch[k].push_back(gens[k]);
      if (k == 0) stretch_seconds.push_back(elapsed());
      if (moves_messages) transport.progress();
    } while (runs_on(k));
  };
  auto arrive = [&] {
    const auto arrivals = phases.waited(phases.migrate, [&] { return transport.receive_migrants(P, s.topology); });
    ++migrations_received;
    for (std::size_t k = 0; k < islands.size(); ++k) gens[k] = islands[k].immigrate(gens[k], arrivals[k]);
  };
  while (!islands.front().done(gens.front()) && !stopping) {
    Phases::timed(phases.evaluate, [&] {
      // One island (a rank's): in this thread, which moves the rank's messages on between generations.
      if (islands.size() == 1) run_on(0, true);
      else tbb::parallel_for(std::size_t(0), islands.size(), [&](std::size_t k) { run_on(k, false); });
    });
    if (islands.front().migrates_after(gens.front(), s.migration_every) && P > 1) {
      // Delayed: the arrivals of migration j - delay come in first, and the emigrants are chosen
      // after them (from the generation stored, so that a resume can choose them again).
      if (delay > 0 && islands.front().migration(gens.front(), s.migration_every) > delay) arrive();
      std::vector<std::vector<opt::Individual>> out;
      for (std::size_t k = 0; k < islands.size(); ++k) out.push_back(islands[k].emigrants(gens[k], s.migrants));
      transport.send_migrants(out, P, s.topology);
      ++migrations_sent;
      if (delay == 0) arrive();
      for (std::size_t k = 0; k < islands.size(); ++k) stretch[k].back() = gens[k];
    }
    stopping = meet(false);
  }
  // The last meetings (the writer stores them) and the migrants still on their way (sent by every
  // island alike, so as many to receive as this process sent).
  const double gather_before = phases.gather, stop_before = phases.stop;  // the end's waits go to `end` only
  Phases::timed(phases.end, [&] {
    while (meetings_received < meetings_sent) receive_meeting();
    for (; migrations_received < migrations_sent; ++migrations_received) transport.receive_migrants(P, s.topology);
    transport.finish_sends();
  });
  phases.gather = gather_before, phases.stop = stop_before;
  if (writing) Phases::timed(phases.store, [&] { writing->finish(); });
  r.interrupted = !islands.front().done(gens.front());
  if (transport.writer()) r.last = merge(base, problem, last);
  if (base.pareto() && transport.writer())
    std::stable_sort(r.last.population.begin(), r.last.population.end(),
                     [&](const opt::Individual& a, const opt::Individual& b) { return problem.better(a.score, b.score); });
  r.seconds = seconds_before + elapsed();

  // Every process's phases at the writer's log (--verbose): experiments/islands/speed.sh reads them.
  long local_evals = -local_evals_before;
  for (const auto& g : gens) local_evals += g.evaluations;
  char line[400];
  std::snprintf(line, sizeof line,
                "islands %s: evaluations %ld wall %.4f cpu %.4f evaluate %.4f migrate %.4f gather %.4f store %.4f"
                " stop %.4f end %.4f",
                (std::to_string(mine.front()) + (mine.size() > 1 ? "-" + std::to_string(mine.back()) : "")).c_str(), local_evals, elapsed(), process_cpu_seconds() - cpu0,
                phases.evaluate, phases.migrate, phases.gather, phases.store, phases.stop, phases.end);
  std::string mine_line = line;
  if (writing) {
    const IslandWriter::Times w = writing->times();
    std::snprintf(line, sizeof line, " commit_wall %.4f commit_cpu %.4f transactions %ld", w.wall, w.cpu, w.transactions);
    mine_line += line;
  }
  for (const std::string& each : transport.gather_text(mine_line)) spdlog::debug("timing: {}", each);
  // Each stored generation's work of every process, one line a process, when asked for.
  std::string works;
  for (const double w : phases.work) works += std::to_string(w) + " ";
  const std::vector<std::string> every_work = transport.gather_text(works);
  if (const char* path = std::getenv("MTCS_ISLANDS_WORK_FILE"); path && transport.writer()) {
    std::ofstream out(path);
    for (const std::string& each : every_work) out << each << "\n";
  }
  return r;
}

}  // namespace mtcs::run
