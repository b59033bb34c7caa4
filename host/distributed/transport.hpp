// SPDX-License-Identifier: Apache-2.0
#pragma once
// How ranks exchange bytes: MPI (mpi_transport.cpp) when fgr was built with it, nothing otherwise
// (no_transport.cpp). Cluster puts its messages on top.

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fgr {

struct Membership {
    int rank = 0;
    int size = 1;
    int local_rank = 0;
    std::string host;
    // Set when a launcher started several ranks but this build cannot join them.
    std::string unavailable;
};

class Transport {
public:
    virtual ~Transport() = default;
    virtual void send(int to, std::span<const uint8_t> bytes) = 0;
    // The next message from `from` (or any rank, -1) with its sender, if one has arrived.
    virtual std::optional<std::pair<int, std::vector<uint8_t>>> try_receive(int from) = 0;
    virtual void finalize() = 0;
};

// Joins the launcher's job when it started more than one rank; null (alone) otherwise.
std::unique_ptr<Transport> join_transport(int* argc, char*** argv, Membership& membership);

// The MPI transport is fgr's module libfgr_mpi.so (scene/modules.hpp, host/distributed/mpi/):
// join_transport loads it only when a launcher started several ranks, so a plain `fgr render`
// does not load Open MPI and the libraries it pulls in. Its entry point returns this table.
struct MpiModule {
    int version;  // kMpiModuleVersion of the tree the module was built from
    // MPI_Init and the membership; the transport is the caller's to delete. Throws
    // std::runtime_error when MPI fails.
    Transport* (*join)(int* argc, char*** argv, Membership& membership);
};
inline constexpr int kMpiModuleVersion = 1;
inline constexpr const char* kMpiModuleName = "libfgr_mpi.so";
inline constexpr const char* kMpiModuleEntry = "fgr_mpi_module";

}  // namespace fgr
