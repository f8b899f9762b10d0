#pragma once
// The island model on a mold (mtcs optimize --islands P): P populations of the run's optimiser
// (ES or SMS-EMOA), island i seeded by opt::island_seed(run seed, i), each with 1/P of the
// evaluation budget, one stored generation at a time (an ES generation; SMS-EMOA's mu steps).
// Every `migration_every` generations each island sends `migrants` to its neighbours (ring or
// fully connected). With `migration_delay` d = 0 the migrants are chosen from the populations
// before any arrival and arrive at once; with d >= 1 the migrants an island sends at its j-th
// migration (chosen after that migration's arrivals) arrive at the receiver's migration j + d, so
// an island sends without waiting and only waits when those of d migrations ago are not there yet.
// Either way the same seed, P and d give the same run, bit for bit, whatever the threads or
// processes. The islands meet only at migrations (and at the end, and at least every 10
// generations): between meetings each runs on without waiting for the others. The islands run in
// this process's threads, or one per MPI rank (IslandTransport); rank 0 gets every island's
// generations since a meeting d meetings later (at once when d = 0) and stores them, and the
// archipelago's (all members), in the run store, from a thread of its own (the islands go on
// meanwhile), whole generations per transaction: a resumed run continues exactly from the last
// stored one (the migrants then on their way are chosen again from the stored generations they
// came from). A stop (Ctrl-C) seen by rank 0 at a meeting ends the run d meetings later, at the
// same generation on every island. Waiting ranks sleep between polls (MPI's own waits would spin
// on the cores the others need).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mtcs/opt/migration.h"
#include "mtcs/run/mold_run.h"
#include "mtcs/run/stored_run.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

struct IslandSettings {
  int islands = 0;           // 0: one population, no islands
  int migration_every = 10;  // stored generations between migrations
  int migrants = 1;          // sent by each island at each migration
  int migration_delay = 1;   // migrations between a send and its arrival (0: at once, in lockstep)
  opt::Topology topology = opt::Topology::ring;

  // The text stored in the run's meta ("islands"), read back on resume (a store without a
  // migration_delay was made before it existed: 0).
  std::string to_text() const;
  // io::InputError naming `origin` and the field.
  static IslandSettings parse(const std::string& text, const std::string& origin);
};

// Where the islands live: all in this process (threads), or one per MPI rank. Every collective
// call is made by each process at the same point of the run. The send_/receive_ calls are
// messages in order: a receive_ returns the oldest message of its kind not yet received, waiting
// (sleeping between polls) only if it is not there yet; a send_ never waits.
class IslandTransport {
 public:
  virtual ~IslandTransport() = default;
  // This process's islands, of `islands` in all.
  virtual std::vector<int> local(int islands) const = 0;
  // Whether this process writes the store and the outputs (rank 0).
  virtual bool writer() const = 0;
  // Each local island's emigrants of one migration, to the islands that receive from it.
  virtual void send_migrants(const std::vector<std::vector<opt::Individual>>& outgoing, int islands,
                             opt::Topology topology) = 0;
  // Each local island's arrivals of the oldest migration not received, sources in the order
  // opt::migration_sources gives.
  virtual std::vector<std::vector<opt::Individual>> receive_migrants(int islands, opt::Topology topology) = 0;
  // This process's islands' generations since the last meeting (each island's in generation
  // order), to the writer.
  virtual void send_stretch(std::vector<std::vector<opt::Generation>> local, int islands) = 0;
  // At the writer: every island's oldest stretch not received, in island order; elsewhere empty.
  virtual std::vector<std::vector<opt::Generation>> receive_stretch(int islands) = 0;
  // The writer's decision to stop (its `value`; elsewhere ignored), to every process.
  virtual void send_stop(bool value) = 0;
  // The oldest decision not received.
  virtual bool receive_stop() = 0;
  // Moves this process's messages on (MPI: a large message goes only while both ends call MPI);
  // cheap, called between generations by the thread that runs a rank's island.
  virtual void progress() {}
  // Returns when every message this process sent has left it (call after receiving all).
  virtual void finish_sends() {}
  // The writer's generations of every island, each island's to the process that runs it.
  virtual std::vector<std::vector<opt::Generation>> scatter(const std::vector<std::vector<opt::Generation>>& all,
                                                            int islands) = 0;
  // The writer's value, everywhere.
  virtual bool broadcast(bool value) = 0;
  virtual std::string broadcast(const std::string& value) = 0;
  // True everywhere when it is true everywhere.
  virtual bool all(bool value) = 0;
  // Every process's text at the writer (in rank order); elsewhere empty.
  virtual std::vector<std::string> gather_text(const std::string& local) = 0;
};

// All islands in this process, stepped in parallel (TBB) or one after another.
std::unique_ptr<IslandTransport> thread_transport();
// One island per MPI rank when this process was started by mpirun and mtcs was built with MPI
// (MTCS_WITH_MPI); otherwise nullptr. Initialises MPI; the transport's end finalises it.
std::unique_ptr<IslandTransport> mpi_transport();
// The number of ranks mpirun started, or 0 outside mpirun.
int mpi_launch_size();
// Worker threads a rank takes by default: the machine's cores shared by the ranks mpirun started
// on it (at least 1); 0 outside mpirun (all cores). More threads than cores would make each
// rank's threads wait for each other's cores.
int threads_per_rank();

// Runs the archipelago from the store's last generation (resume) or fresh populations to the
// budget, or until stop() (the writer's) is true at a meeting of the islands. `db` is the writer's
// store (nullptr elsewhere); `on_line` gets each stored generation's index and its live line,
// made when asked for (the writer; most lines are not printed, and making them costs the writer's
// island).
StoredRun run_islands(const MoldOptimizer& base, const MoldProblem& problem, const IslandSettings& settings,
                      IslandTransport& transport, store::RunStore* db,
                      const std::function<void(int generation, const std::function<std::string()>& line)>& on_line,
                      const std::function<bool()>& stop = {});

// The live line: the archipelago's progress (all islands' members) and each island's best (ES)
// or hypervolume (SMS-EMOA).
std::string island_progress_line(const MoldOptimizer& base, const opt::Generation& merged,
                                 const std::vector<opt::Generation>& islands, double seconds, long evaluations);

}  // namespace mtcs::run
