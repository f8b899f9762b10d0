#include "mtcs/serve/job_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mtcs/serve/credentials.h"

namespace mtcs::serve {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read_text(const fs::path& file, std::size_t limit = 1 << 20) {
  std::ifstream in(file, std::ios::binary);
  std::string text(limit, '\0');
  in.read(text.data(), std::streamsize(limit));
  text.resize(std::size_t(in.gcount()));
  return text;
}

// The last non-empty line a failed child printed: the CLI's one-line error (file:line:field).
std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

std::string quantised(const json& point, double step) {
  std::string out;
  for (const auto& v : point) out += std::to_string(std::llround(v.get<double>() / step)) + ",";
  return out;
}

// A check runs this very binary: built with AddressSanitizer, it maps terabytes of shadow
// memory at start, which an address-space limit refuses (the limit is left off there).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// A number as the CLI reads it back bit for bit (std::to_string keeps six decimals).
std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

}  // namespace

std::string interference_key(const std::string& a, const std::string& b, const json& group) {
  // Each face is placed on a grid an eighth of its own size (a mesh in metres and one in
  // millimetres alike) and its area on a quarter-octave scale.
  auto face = [&](const char* centroid, const char* area) {
    const double size = group.at(area).get<double>();
    return quantised(group.at(centroid), std::max(std::sqrt(size) / 8, 1e-12)) + "|" +
           std::to_string(std::lround(4 * std::log2(std::max(size, 1e-300))));
  };
  const std::string text = "interference|" + a + "|" + face("centroid_a", "area_a") + "|" + b + "|" +
                           face("centroid_b", "area_b");
  Sha256 h;
  h.add(text.data(), text.size());
  return h.hex().substr(0, 24);
}

JobRunner::JobRunner(ReviewStore& store, EventBroker& events, const BlobStore& blobs, fs::path mtcs_binary,
                     int workers, JobLimits limits)
    : store_(store), events_(events), blobs_(blobs), binary_(std::move(mtcs_binary)), limits_(limits) {
  for (const Job& job : store_.interrupt_running())
    events_.publish(job.project, "job.finished", 0, {{"job", job.id}, {"state", "interrupted"}});
  for (int i = 0; i < std::max(1, workers); ++i) workers_.emplace_back([this] { work(); });
}

JobRunner::~JobRunner() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& [id, asked] : cancelled_) asked = true;
  }
  queued_.notify_all();
  for (auto& w : workers_) w.join();
}

void JobRunner::wake() {
  {
    std::lock_guard lock(mutex_);
    pending_ = true;
  }
  queued_.notify_one();
}

bool JobRunner::cancel(long job) {
  std::lock_guard lock(mutex_);
  if (auto it = cancelled_.find(job); it != cancelled_.end()) {
    it->second = true;
    return true;
  }
  return false;
}

void JobRunner::work() {
  for (;;) {
    std::optional<Job> job;
    {
      std::unique_lock lock(mutex_);
      queued_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_ || pending_; });
      if (stopping_) return;
      pending_ = false;
      job = store_.claim_next();
      if (!job) continue;
      cancelled_[job->id] = false;
    }
    try {
      run(*job);
    } catch (const std::exception& e) {
      store_.set_job_state(job->id, "failed", e.what());
      events_.publish(job->project, "job.finished", 0, {{"job", job->id}, {"state", "failed"}, {"message", e.what()}});
    }
    std::lock_guard lock(mutex_);
    cancelled_.erase(job->id);
  }
}

int JobRunner::run_child(long job, const std::vector<std::string>& argv, const fs::path& folder) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  char path_env[] = "PATH=/usr/local/bin:/usr/bin:/bin";
  char lang_env[] = "LANG=C.UTF-8";
  char* env[] = {path_env, lang_env, nullptr};
  const int out = ::open((folder / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  const int err = ::open((folder / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (out < 0 || err < 0) throw std::runtime_error("cannot open the job's output files in " + folder.string());
  const std::string dir = folder.string();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {  // only async-signal-safe calls until execve
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(126);
    const rlimit memory{limits_.memory_bytes, limits_.memory_bytes};
    const rlimit cpu{rlim_t(limits_.wall_seconds), rlim_t(limits_.wall_seconds)};
    const rlimit file{limits_.file_bytes, limits_.file_bytes};
    if (!kSanitized) ::setrlimit(RLIMIT_AS, &memory);
    ::setrlimit(RLIMIT_CPU, &cpu);
    ::setrlimit(RLIMIT_FSIZE, &file);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::close_range(3, ~0U, 0);  // the server's sockets and files (httplib's are not CLOEXEC)
    sigset_t none;  // `mtcs serve` blocks SIGINT and SIGTERM in its threads; the check must not
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execve(args[0], args.data(), env);
    ::_exit(127);
  }
  ::close(out);
  ::close(err);
  if (pid < 0) throw std::runtime_error("cannot start a check (fork failed)");
  const auto start = std::chrono::steady_clock::now();
  bool terminated = false, timed_out = false;
  std::chrono::steady_clock::time_point term_time;
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      if (terminated) return timed_out ? -2 : -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    }
    bool stop = false;
    {
      std::lock_guard lock(mutex_);
      stop = cancelled_[job];
    }
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - start).count() > limits_.wall_seconds) stop = timed_out = true;
    if (stop && !terminated) {
      ::kill(-pid, SIGTERM);
      terminated = true;
      term_time = now;
    } else if (terminated && now - term_time > std::chrono::seconds(3)) {
      ::kill(-pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void JobRunner::run(const Job& job) {
  events_.publish(job.project, "job.started", 0, {{"job", job.id}, {"kind", job.kind}});
  const fs::path folder = blobs_.root() / "jobs" / std::to_string(job.id);
  fs::create_directories(folder);
  if (job.kind != "interference") throw std::runtime_error("unknown job kind " + job.kind);

  const auto va = store_.version(job.project, job.inputs.at("a").get<long>());
  const auto vb = store_.version(job.project, job.inputs.at("b").get<long>());
  if (!va || !vb) throw std::runtime_error("a version of the check is gone");
  // The readers choose by extension: the blob is linked under the name's extension.
  auto link = [&](const Version& v, const std::string& stem) {
    const fs::path target = folder / (stem + fs::path(v.filename).extension().string());
    std::error_code ignored;
    fs::remove(target, ignored);
    fs::create_symlink(blobs_.path_of(v.blob), target);
    return target.filename().string();
  };
  std::vector<std::string> argv{binary_.string(), "interfere", link(*va, "a"), link(*vb, "b"), "--json",
                                "--report", "page.html"};
  const json& t = job.inputs.at("translate");
  argv.push_back("--translate=" + exact(t[0].get<double>()) + "," + exact(t[1].get<double>()) + "," +
                 exact(t[2].get<double>()));
  if (job.inputs.contains("touch_tolerance"))
    argv.push_back("--touch-tolerance=" + exact(job.inputs["touch_tolerance"].get<double>()));

  const int code = run_child(job.id, argv, folder);
  if (code == -2) {
    const std::string message = "stopped after " + exact(limits_.wall_seconds) + " s, the limit of a check";
    store_.set_job_state(job.id, "failed", message);
    events_.publish(job.project, "job.finished", 0, {{"job", job.id}, {"state", "failed"}, {"message", message}});
    return;
  }
  if (code == -1) {  // stopped: by a user, or with the server
    bool stopping;
    {
      std::lock_guard lock(mutex_);
      stopping = stopping_;
    }
    const std::string state = stopping ? "interrupted" : "cancelled";
    store_.set_job_state(job.id, state, stopping ? "the server stopped while it ran" : "cancelled while it ran");
    events_.publish(job.project, "job.finished", 0, {{"job", job.id}, {"state", state}});
    return;
  }
  if (code != 0) {
    const std::string message = last_line(read_text(folder / "stderr.txt"));
    store_.set_job_state(job.id, "failed", message);
    events_.publish(job.project, "job.finished", 0, {{"job", job.id}, {"state", "failed"}, {"message", message}});
    return;
  }
  const json report = json::parse(read_text(folder / "stdout.txt", 256u << 20));
  std::vector<Finding> found;
  std::map<std::string, int> seen;
  for (const json& g : report.at("groups")) {
    json payload = g;
    payload["component_a"] = va->component, payload["component_b"] = vb->component;
    payload["version_a"] = va->seq, payload["version_b"] = vb->seq;
    std::string key = interference_key(va->component, vb->component, g);
    if (const int n = seen[key]++; n > 0) key += "." + std::to_string(n);  // two faces alike: told apart by order
    found.push_back({key, "", payload});
  }
  const std::vector<Finding> settled = store_.settle_findings(job, std::move(found));
  json counts{{"new", 0}, {"persistent", 0}, {"resolved", 0}};
  for (const Finding& f : settled) {
    counts[f.state] = counts[f.state].get<int>() + 1;
    const std::string versions = va->component + " v" + std::to_string(va->seq) + ", " + vb->component + " v" +
                                 std::to_string(vb->seq);
    const std::string note = f.state == "resolved" ? "check " + std::to_string(job.id) + " on " + versions +
                                                         ": no longer found (resolved)"
                             : f.state == "persistent" ? "check " + std::to_string(job.id) + " on " + versions +
                                                             ": still there (" + std::to_string(f.payload.value("pairs", 0)) +
                                                             " triangle pairs)"
                                                       : "";
    if (note.empty()) continue;
    for (long topic : store_.note_on_finding(job.project, f.key, note))
      events_.publish(job.project, "comment.created", 0, {{"topic", topic}, {"text", note}, {"author", "mtcs"}});
  }
  const json result{{"pair_count", report.at("pair_count")},
                    {"interferes", report.at("interferes")},
                    {"distance", report.at("distance")},
                    {"groups", report.at("groups").size()},
                    {"findings", counts}};
  store_.set_job_state(job.id, "succeeded", "", result);
  events_.publish(job.project, "job.finished", 0, {{"job", job.id}, {"state", "succeeded"}, {"result", result}});
}

}  // namespace mtcs::serve
