#pragma once
// The void's panel matrix A = 1/2 - K' (void_surface.h) depends on the wall's geometry, the
// block's images and the panels alone: not on the heat, the film or the coolant. It is most of
// a mesh part's model (the gear's 911 panels: 14 of its 17 s on a loaded machine), and the same
// part in the same block gives the same matrix. So do the panels' potentials at the model's
// samples, at the faces and at their own points (most of what a film's model builds again:
// `mtcs thermal`'s cycle solves the part at 2-3 films). So they are kept: in memory, the most
// recently used (kKeptBytes), and the panel matrix and the potentials at the panels' own points
// (as costly) in the disk cache (mtcs/io/disk_cache.h) too, under a key of every input and of
// the digest of the sources that compute them, so a kept matrix is bit for bit what a fresh
// build gives.
// Private to src/thermal.

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <memory>
#include <string_view>

#include "mtcs/io/disk_cache.h"

namespace mtcs::thermal {

// A key for one of the void's matrices: `kind` (a file-name prefix), the sources' digest, the
// CPU's kernel set and glibc's version (libm's log and atan2 may differ between its FMA and plain
// paths and between releases); the caller adds the inputs.
io::CacheKey panel_matrix_key(std::string_view kind);

// The matrices kept in memory take at most this many bytes (the last used always kept).
constexpr std::size_t kKeptBytes = std::size_t(256) << 20;

// Where a matrix is kept: in memory for this process, or on disk as well (the panel matrix:
// seconds to build, milliseconds to read; the potentials are about as fast to compute as to read).
enum class Keep { memory, disk };

// The rows x cols matrix of key: kept, or computed by compute(M) into M (sized rows x cols) and
// kept (shared, not copied: a model holds the samples' potentials as kept). One of more than
// kKeptBytes / 2 is computed each time and never kept.
std::shared_ptr<const Eigen::MatrixXd> kept_panel_matrix(const io::CacheKey& key, Eigen::Index rows, Eigen::Index cols,
                                                         Keep keep, const std::function<void(Eigen::MatrixXd&)>& compute);

}  // namespace mtcs::thermal
