// SPDX-License-Identifier: Apache-2.0
// fgr built with MPI: the transport is the module libfgr_mpi.so (transport.hpp), loaded only when
// a launcher started several ranks. A plain `fgr render` does not start MPI either: its runtime
// would cost start-up time and, on some systems, print warnings about networks it cannot use.
#include <stdexcept>

#include "distributed/cluster.hpp"
#include "distributed/transport.hpp"
#include "scene/modules.hpp"

namespace fgr {

std::unique_ptr<Transport> join_transport(int* argc, char*** argv, Membership& membership) {
    if (launcher_world_size() <= 1) return nullptr;
    const MpiModule* module = nullptr;
    try {
        module = &module_table<MpiModule>(kMpiModuleName, kMpiModuleEntry, kMpiModuleVersion,
                                          "sharing a render between mpirun's ranks");
    } catch (const std::runtime_error& error) {
        // As a build without MPI would: every rank alone, and rank 0 says why.
        membership.rank = launcher_world_rank();
        membership.unavailable = error.what();
        return nullptr;
    }
    return std::unique_ptr<Transport>(module->join(argc, argv, membership));
}

}  // namespace fgr
