#pragma once
// What a line-sink model with the part's void holds at its samples, checked against what the
// machine has before it is filled: a part too big for the machine gets an error with the size it
// would need, not a swapping machine or an out-of-memory kill halfway. (The panels' matrices,
// at most 3 000 panels, ~250 MB, are built by then.) Private to src/thermal.

#include <cstddef>
#include <optional>

namespace mtcs::thermal {

// Bytes a model may plan for: the least of the memory available now (/proc/meminfo's
// MemAvailable), the address-space limit (ulimit -v) and $MTCS_MEMORY_LIMIT (MB: a shared
// machine's share); none when none of them is known.
std::optional<std::size_t> memory_budget();

// The model's largest part with the void, the samples' potentials (double, and in float
// transposed): throws std::runtime_error naming its size and how to bring it down when it
// exceeds memory_budget().
void check_void_model_memory(std::size_t panels, std::size_t samples);

}  // namespace mtcs::thermal
