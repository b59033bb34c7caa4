// SPDX-License-Identifier: Apache-2.0
// fgr built without MPI: every process is a job of its own. Started by mpirun on several ranks,
// it says so (rank 0 only) instead of letting N copies race to write the same file.
#include "distributed/cluster.hpp"
#include "distributed/transport.hpp"

namespace fgr {

std::unique_ptr<Transport> join_transport(int*, char***, Membership& membership) {
    if (launcher_world_size() > 1) {
        membership.rank = launcher_world_rank();
        membership.unavailable =
            "this fgr was built without MPI, so it cannot share a render between mpirun's ranks "
            "(install libopenmpi-dev and build with -DFGR_MPI=ON, or install the packages fgr and "
            "fgr-mpi)";
    }
    return nullptr;
}

}  // namespace fgr
