// One island per MPI rank (mtcs built with MTCS_WITH_MPI, started by mpirun): migrants go
// point to point around the ring, or to every rank (all-gather) when fully connected; rank 0
// gathers every island's generations since the last meeting to store them. Messages are generations and migrants as
// bytes (island_wire.h), every number as its exact bits. Every call waits through await():
// MPI's blocking calls poll without end, which takes the core of a rank that still evaluates
// (2 ranks on 2 shared cores: 0.7x the evaluations/s of one rank, experiments/islands).
#include <mpi.h>
#include <sys/prctl.h>

#include <chrono>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "island_wire.h"
#include "mtcs/run/islands.h"

namespace mtcs::run {
namespace {

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// Waits for the requests, polling MPI (which moves the messages on) a few microseconds, then
// sleeping between polls: 50 us for the first millisecond (a rank just behind), 200 us after.
void await(MPI_Request* requests, int n, const char* what) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  for (int polls = 0;; ++polls) {
    int done = 0;
    check(MPI_Testall(n, requests, &done, MPI_STATUSES_IGNORE), what);
    if (done) return;
    if (polls < 20) continue;
    const bool long_wait = clock::now() - t0 > std::chrono::milliseconds(1);
    std::this_thread::sleep_for(std::chrono::microseconds(long_wait ? 200 : 50));
  }
}
void await(MPI_Request& request, const char* what) { await(&request, 1, what); }

class MpiTransport final : public IslandTransport {
 public:
  MpiTransport() {
    int ready = 0;
    MPI_Initialized(&ready);
    if (!ready) {
      int provided = 0;
      check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "init");
      owns_ = true;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    ::prctl(PR_SET_TIMERSLACK, 1000UL);  // await()'s sleeps end within 1 us of asked, not 50 us
  }
  // Left by an error (the exception on its way to main's message and exit code): no finalize,
  // which would wait for ranks that wait for this one; mpirun ends them when this rank exits.
  ~MpiTransport() override {
    if (owns_ && std::uncaught_exceptions() == unwinding_) MPI_Finalize();
  }

  std::vector<int> local(int islands) const override {
    if (islands != size_)
      throw std::runtime_error("islands: " + std::to_string(islands) + " islands on " + std::to_string(size_) + " ranks");
    return {rank_};
  }
  bool writer() const override { return rank_ == 0; }

  std::vector<std::vector<opt::Individual>> migrate(const std::vector<std::vector<opt::Individual>>& outgoing, int islands,
                                                    opt::Topology topology) override {
    const std::string mine = wire::encode(outgoing.front());
    std::vector<opt::Individual> arrivals;
    if (topology == opt::Topology::ring) {
      const int to = (rank_ + 1) % islands, from = (rank_ + islands - 1) % islands;
      int size = int(mine.size()), incoming = 0;
      MPI_Request r[2];
      check(MPI_Irecv(&incoming, 1, MPI_INT, from, 1, MPI_COMM_WORLD, &r[0]), "ring sizes");
      check(MPI_Isend(&size, 1, MPI_INT, to, 1, MPI_COMM_WORLD, &r[1]), "ring sizes");
      await(r, 2, "ring sizes");
      std::string bytes(std::size_t(incoming), '\0');
      check(MPI_Irecv(bytes.data(), incoming, MPI_BYTE, from, 2, MPI_COMM_WORLD, &r[0]), "ring migrants");
      check(MPI_Isend(mine.data(), size, MPI_BYTE, to, 2, MPI_COMM_WORLD, &r[1]), "ring migrants");
      await(r, 2, "ring migrants");
      arrivals = wire::decode_individuals(bytes);
    } else {
      const std::vector<std::string> every = all_gather(mine);
      for (const int s : opt::migration_sources(topology, islands, rank_)) {
        const auto part = wire::decode_individuals(every[std::size_t(s)]);
        arrivals.insert(arrivals.end(), part.begin(), part.end());
      }
    }
    return {arrivals};
  }

  std::vector<std::vector<opt::Generation>> gather(std::vector<std::vector<opt::Generation>> local, int) override {
    std::vector<std::vector<opt::Generation>> out;
    // Rank 0 keeps its own island's generations as they are (no bytes to itself).
    for (std::string& bytes : gather_bytes(rank_ == 0 ? std::string() : wire::encode(local.front()))) {
      if (out.empty()) out.push_back(std::move(local.front()));
      else out.push_back(wire::decode_generations(bytes));
    }
    return out;
  }

  std::vector<std::string> gather_text(const std::string& local) override { return gather_bytes(local); }

  std::vector<opt::Generation> scatter(const std::vector<opt::Generation>& all, int) override {
    if (rank_ == 0) {
      for (int r = 1; r < size_; ++r) {
        const std::string bytes = wire::encode(all[std::size_t(r)]);
        int size = int(bytes.size());
        MPI_Request req;
        check(MPI_Isend(&size, 1, MPI_INT, r, 3, MPI_COMM_WORLD, &req), "scatter size");
        await(req, "scatter size");
        check(MPI_Isend(bytes.data(), size, MPI_BYTE, r, 4, MPI_COMM_WORLD, &req), "scatter generation");
        await(req, "scatter generation");
      }
      return {all.front()};
    }
    int size = 0;
    MPI_Request req;
    check(MPI_Irecv(&size, 1, MPI_INT, 0, 3, MPI_COMM_WORLD, &req), "scatter size");
    await(req, "scatter size");
    std::string bytes(std::size_t(size), '\0');
    check(MPI_Irecv(bytes.data(), size, MPI_BYTE, 0, 4, MPI_COMM_WORLD, &req), "scatter generation");
    await(req, "scatter generation");
    return {wire::decode_generation(bytes)};
  }

  bool broadcast(bool value) override {
    int v = value ? 1 : 0;
    MPI_Request req;
    check(MPI_Ibcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD, &req), "broadcast");
    await(req, "broadcast");
    return v != 0;
  }
  std::string broadcast(const std::string& value) override {
    int size = int(value.size());
    MPI_Request req;
    check(MPI_Ibcast(&size, 1, MPI_INT, 0, MPI_COMM_WORLD, &req), "broadcast size");
    await(req, "broadcast size");
    std::string out = rank_ == 0 ? value : std::string(std::size_t(size), '\0');
    check(MPI_Ibcast(out.data(), size, MPI_BYTE, 0, MPI_COMM_WORLD, &req), "broadcast text");
    await(req, "broadcast text");
    return out;
  }
  bool all(bool value) override {
    int v = value ? 1 : 0, out = 0;
    MPI_Request req;
    check(MPI_Iallreduce(&v, &out, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD, &req), "all");
    await(req, "all");
    return out != 0;
  }

 private:
  // Every rank's bytes at rank 0 (in rank order); elsewhere empty.
  std::vector<std::string> gather_bytes(const std::string& mine) {
    int size = int(mine.size());
    const auto ranks = static_cast<std::size_t>(size_);
    std::vector<int> sizes(ranks), offsets(ranks);
    MPI_Request req;
    check(MPI_Igather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &req), "gather sizes");
    await(req, "gather sizes");
    std::exclusive_scan(sizes.begin(), sizes.end(), offsets.begin(), 0);
    std::string all(rank_ == 0 ? std::size_t(offsets.back() + sizes.back()) : 0, '\0');
    check(MPI_Igatherv(mine.data(), size, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD,
                       &req),
          "gather generations");
    await(req, "gather generations");
    std::vector<std::string> out;
    if (rank_ == 0)
      for (int r = 0; r < size_; ++r)
        out.push_back(all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(sizes[std::size_t(r)])));
    return out;
  }

  std::vector<std::string> all_gather(const std::string& mine) {
    int size = int(mine.size());
    const auto ranks = static_cast<std::size_t>(size_);
    std::vector<int> sizes(ranks), offsets(ranks);
    MPI_Request req;
    check(MPI_Iallgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD, &req), "all-gather sizes");
    await(req, "all-gather sizes");
    std::exclusive_scan(sizes.begin(), sizes.end(), offsets.begin(), 0);
    std::string all(std::size_t(offsets.back() + sizes.back()), '\0');
    check(MPI_Iallgatherv(mine.data(), size, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, MPI_COMM_WORLD,
                          &req),
          "all-gather migrants");
    await(req, "all-gather migrants");
    std::vector<std::string> out;
    for (int r = 0; r < size_; ++r)
      out.push_back(all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(sizes[std::size_t(r)])));
    return out;
  }

  int rank_ = 0, size_ = 1;
  bool owns_ = false;
  int unwinding_ = std::uncaught_exceptions();
};

}  // namespace

std::unique_ptr<IslandTransport> mpi_transport() {
  if (mpi_launch_size() == 0) return nullptr;
  return std::make_unique<MpiTransport>();
}

}  // namespace mtcs::run
