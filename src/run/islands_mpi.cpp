// One island per MPI rank (mtcs built with MTCS_WITH_MPI, started by mpirun): migrants go
// point to point to the ranks that receive from this one (the next on the ring, or all); every
// rank sends its generations since the last meeting to rank 0, and rank 0 its stop to every rank.
// These messages are sent without waiting and received in order on a communicator of their own
// (an inbox: each arriving message is received as soon as the rank looks, so a large one moves
// while both ranks go on). Messages are generations and migrants as bytes (island_wire.h), every
// number as its exact bits. Every wait polls, then sleeps: MPI's blocking calls poll without end,
// which takes the core of a rank that still evaluates (2 ranks on 2 shared cores: 0.7x the
// evaluations/s of one rank, experiments/islands).
#include <mpi.h>
#include <sys/prctl.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <exception>
#include <list>
#include <map>
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

// Waits until `done()` (which polls MPI, moving the messages on): a few polls at once, then
// sleeping between polls: 50 us for the first millisecond (a rank just behind), 200 us after.
template <class Done>
void wait_until(Done&& done) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  for (int polls = 0;; ++polls) {
    if (done()) return;
    if (polls < 20) continue;
    const bool long_wait = clock::now() - t0 > std::chrono::milliseconds(1);
    std::this_thread::sleep_for(std::chrono::microseconds(long_wait ? 200 : 50));
  }
}
void await(MPI_Request* requests, int n, const char* what) {
  wait_until([&] {
    int done = 0;
    check(MPI_Testall(n, requests, &done, MPI_STATUSES_IGNORE), what);
    return done != 0;
  });
}
void await(MPI_Request& request, const char* what) { await(&request, 1, what); }

// The kinds of message in the inbox (tags of the transport's own communicator).
enum Tag : int { kMigrants = 1, kStretch = 2, kStop = 3 };

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
    check(MPI_Comm_dup(MPI_COMM_WORLD, &messages_), "communicator");
    ::prctl(PR_SET_TIMERSLACK, 1000UL);  // await()'s sleeps end within 1 us of asked, not 50 us
  }
  // Left by an error (the exception on its way to main's message and exit code): no finalize,
  // which would wait for ranks that wait for this one; mpirun ends them when this rank exits.
  ~MpiTransport() override {
    if (owns_ && std::uncaught_exceptions() == unwinding_) {
      MPI_Comm_free(&messages_);
      MPI_Finalize();
    }
  }

  std::vector<int> local(int islands) const override {
    if (islands != size_)
      throw std::runtime_error("islands: " + std::to_string(islands) + " islands on " + std::to_string(size_) + " ranks");
    return {rank_};
  }
  bool writer() const override { return rank_ == 0; }

  void send_migrants(const std::vector<std::vector<opt::Individual>>& outgoing, int islands,
                     opt::Topology topology) override {
    const std::string bytes = wire::encode(outgoing.front());
    for (int to = 0; to < islands; ++to) {
      const std::vector<int> from = opt::migration_sources(topology, islands, to);
      if (to != rank_ && std::find(from.begin(), from.end(), rank_) != from.end()) send(to, kMigrants, bytes);
    }
  }
  std::vector<std::vector<opt::Individual>> receive_migrants(int islands, opt::Topology topology) override {
    std::vector<opt::Individual> arrivals;
    for (const int from : opt::migration_sources(topology, islands, rank_)) {
      const auto part = wire::decode_individuals(receive(from, kMigrants));
      arrivals.insert(arrivals.end(), part.begin(), part.end());
    }
    return {arrivals};
  }

  // Rank 0 keeps its own island's generations as they are (no bytes to itself).
  void send_stretch(std::vector<std::vector<opt::Generation>> local, int) override {
    if (rank_ == 0) own_stretches_.push_back(std::move(local.front()));
    else send(0, kStretch, wire::encode(local.front()));
  }
  std::vector<std::vector<opt::Generation>> receive_stretch(int) override {
    std::vector<std::vector<opt::Generation>> out;
    if (rank_ != 0) return out;
    out.push_back(std::move(own_stretches_.front()));
    own_stretches_.pop_front();
    for (int r = 1; r < size_; ++r) out.push_back(wire::decode_generations(receive(r, kStretch)));
    return out;
  }

  void send_stop(bool value) override {
    if (rank_ != 0) return;
    own_stops_.push_back(value);
    for (int r = 1; r < size_; ++r) send(r, kStop, std::string(1, value ? '1' : '0'));
  }
  bool receive_stop() override {
    if (rank_ != 0) return receive(0, kStop) == "1";
    const bool value = own_stops_.front();
    own_stops_.pop_front();
    return value;
  }

  void progress() override {
    for (auto it = sends_.begin(); it != sends_.end();) {
      int done = 0;
      check(MPI_Test(&it->request, &done, MPI_STATUS_IGNORE), "send");
      it = done ? sends_.erase(it) : std::next(it);
    }
    // Every message that came starts being received (into its sender's and kind's queue).
    for (;;) {
      int found = 0, size = 0;
      MPI_Message message;
      MPI_Status status;
      check(MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, messages_, &found, &message, &status), "probe");
      if (!found) return;
      check(MPI_Get_count(&status, MPI_BYTE, &size), "message size");
      Message& m = inbox_[{status.MPI_SOURCE, status.MPI_TAG}].emplace_back();
      m.bytes.assign(std::size_t(size), '\0');
      check(MPI_Imrecv(m.bytes.data(), size, MPI_BYTE, &message, &m.request), "receive");
    }
  }
  void finish_sends() override {
    wait_until([&] {
      progress();
      return sends_.empty();
    });
  }

  std::vector<std::string> gather_text(const std::string& local) override { return gather_bytes(local); }

  std::vector<std::vector<opt::Generation>> scatter(const std::vector<std::vector<opt::Generation>>& all,
                                                    int) override {
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
    return {wire::decode_generations(bytes)};
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

  // Sends `bytes` to `to` on the transport's communicator without waiting (kept until sent).
  void send(int to, int tag, std::string bytes) {
    Message& m = sends_.emplace_back();
    m.bytes = std::move(bytes);
    check(MPI_Isend(m.bytes.data(), int(m.bytes.size()), MPI_BYTE, to, tag, messages_, &m.request), "send");
  }
  // The oldest message of `tag` from `from` not received, when it is here.
  std::string receive(int from, int tag) {
    std::list<Message>& queue = inbox_[{from, tag}];
    wait_until([&] {
      progress();
      int done = 0;
      if (!queue.empty()) check(MPI_Test(&queue.front().request, &done, MPI_STATUS_IGNORE), "receive");
      return done != 0;
    });
    std::string bytes = std::move(queue.front().bytes);
    queue.pop_front();
    return bytes;
  }

  struct Message {
    std::string bytes;
    MPI_Request request = MPI_REQUEST_NULL;
  };
  std::list<Message> sends_;                          // sent, maybe not yet out
  std::map<std::pair<int, int>, std::list<Message>> inbox_;  // by sender and tag, in order
  std::deque<std::vector<opt::Generation>> own_stretches_;  // rank 0's
  std::deque<bool> own_stops_;                              // rank 0's
  MPI_Comm messages_ = MPI_COMM_NULL;
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
