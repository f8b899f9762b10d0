// mtcs built without MPI (MTCS_WITH_MPI off): islands run in threads only.
#include "mtcs/run/islands.h"

namespace mtcs::run {

std::unique_ptr<IslandTransport> mpi_transport() { return nullptr; }

}  // namespace mtcs::run
