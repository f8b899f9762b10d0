#include "thermal/cavity/panel_matrix_cache.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <utility>

#include <gnu/libc-version.h>
#include <spdlog/spdlog.h>

#include "thermal/cavity/panel_matrix_source.h"  // generated: kPanelMatrixSource
#include "thermal/kernels/cpu_features.h"

namespace mtcs::thermal {
namespace {

using Digest = std::array<unsigned char, 16>;
std::mutex kept_mutex;
std::deque<std::pair<Digest, std::shared_ptr<const Eigen::MatrixXd>>> kept;  // newest first
std::size_t kept_bytes = 0;

std::span<std::byte> bytes_of(Eigen::MatrixXd& m) {
  return std::as_writable_bytes(std::span(m.data(), std::size_t(m.size())));
}

}  // namespace

io::CacheKey panel_matrix_key(std::string_view kind) {
  io::CacheKey key(kind);
  key.add(std::string_view(kPanelMatrixSource));
  key.add_value(int(has_avx2_fma())).add(std::string_view(gnu_get_libc_version()));
  return key;
}

std::shared_ptr<const Eigen::MatrixXd> kept_panel_matrix(const io::CacheKey& key, Eigen::Index rows, Eigen::Index cols,
                                                         Keep keep, const std::function<void(Eigen::MatrixXd&)>& compute) {
  const std::size_t bytes = sizeof(double) * std::size_t(rows) * std::size_t(cols);
  if (bytes > kKeptBytes / 2) {  // a copy kept would double a big part's memory
    auto m = std::make_shared<Eigen::MatrixXd>(rows, cols);
    compute(*m);
    return m;
  }
  const Digest digest = key.digest();
  {
    const std::lock_guard lock(kept_mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (it->first == digest && it->second->rows() == rows && it->second->cols() == cols) {
        auto hit = *it;  // to the front: the least recently used go first
        kept.erase(it);
        kept.push_front(hit);
        return hit.second;
      }
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  auto m = std::make_shared<Eigen::MatrixXd>(rows, cols);
  if (keep == Keep::disk && io::cache_read(key, bytes_of(*m))) {
    spdlog::debug("void panels: {} x {} matrix read from the cache in {:.3f} s", rows, cols, seconds());
  } else {
    compute(*m);
    spdlog::debug("void panels: {} x {} matrix built in {:.1f} s", rows, cols, seconds());
    if (keep == Keep::disk) io::cache_write(key, std::as_bytes(std::span(m->data(), std::size_t(m->size()))));
  }
  // Two threads that missed together both built it (the same bits): one entry is kept.
  const std::lock_guard lock(kept_mutex);
  if (std::none_of(kept.begin(), kept.end(), [&](const auto& k) { return k.first == digest; })) {
    kept.emplace_front(digest, m);
    kept_bytes += bytes;
    while (kept.size() > 1 && kept_bytes > kKeptBytes) {
      kept_bytes -= sizeof(double) * std::size_t(kept.back().second->size());
      kept.pop_back();
    }
  }
  return m;
}

}  // namespace mtcs::thermal
