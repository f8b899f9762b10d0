#pragma once
// The void's panel matrix A = 1/2 - K' (void_surface.h) depends on the wall's geometry, the
// block's images and the panels alone: not on the heat, the film or the coolant. It is most of
// a mesh part's model (the gear's 911 panels: 14 of its 17 s on a loaded machine), and the same
// part in the same block gives the same matrix. So it is kept: in memory, the newest two (a
// command that solves one part at several films, as `mtcs thermal`'s cycle does), and in the
// disk cache (mtcs/io/disk_cache.h) under a key of every input and of the digest of the sources
// that compute it, so a kept matrix is bit for bit what a fresh assembly gives.
// Private to src/thermal.

#include <Eigen/Dense>
#include <functional>
#include <string_view>

#include "mtcs/io/disk_cache.h"

namespace mtcs::thermal {

// A key for the panel matrix: "panel-matrix", the sources' digest, the CPU's kernel set and
// glibc's version (libm's log and atan2 may differ between its FMA and plain paths and between
// releases); the caller adds the inputs.
io::CacheKey panel_matrix_key();

// The n x n matrix of key: kept, or assembled by assemble(A) into A (sized n x n) and kept.
Eigen::MatrixXd kept_panel_matrix(const io::CacheKey& key, Eigen::Index n,
                                  const std::function<void(Eigen::MatrixXd&)>& assemble);

}  // namespace mtcs::thermal
