// SPDX-License-Identifier: Apache-2.0
// The MPI transport: MPI_COMM_WORLD, point-to-point byte messages of one tag. Only the main
// thread calls MPI (MPI_THREAD_FUNNELED): rank 0's own renderer thread never does. Built as the
// module libfgr_mpi.so (transport.hpp), which calls nothing of fgr's but this file.
#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include <climits>
#include <stdexcept>

#include "distributed/transport.hpp"

namespace fgr {
namespace {

constexpr int kTag = 18;

void check(int status, const char* what) {
    if (status != MPI_SUCCESS) {
        char text[MPI_MAX_ERROR_STRING];
        int length = 0;
        MPI_Error_string(status, text, &length);
        throw std::runtime_error(
            fmt::format("MPI {} failed: {}", what, std::string(text, size_t(length))));
    }
}

class MpiTransport final : public Transport {
public:
    void send(int to, std::span<const uint8_t> bytes) override {
        if (bytes.size() > size_t(INT_MAX)) {
            throw std::runtime_error(
                fmt::format("a message of {} bytes is more than MPI sends at once", bytes.size()));
        }
        check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, kTag,
                       MPI_COMM_WORLD),
              "send");
    }

    std::optional<std::pair<int, std::vector<uint8_t>>> try_receive(int from) override {
        int arrived = 0;
        MPI_Status status;
        check(MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, kTag, MPI_COMM_WORLD, &arrived, &status),
              "probe");
        if (!arrived) return std::nullopt;
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        std::vector<uint8_t> bytes(static_cast<size_t>(count));
        check(MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, kTag, MPI_COMM_WORLD,
                       MPI_STATUS_IGNORE),
              "receive");
        return std::make_pair(status.MPI_SOURCE, std::move(bytes));
    }

    void finalize() override {
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (!finalized) MPI_Finalize();
    }
};

Transport* join(int* argc, char*** argv, Membership& membership) {
    int provided = 0;
    check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "init");
    MPI_Comm_rank(MPI_COMM_WORLD, &membership.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &membership.size);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, membership.rank, MPI_INFO_NULL,
                        &node);
    MPI_Comm_rank(node, &membership.local_rank);
    MPI_Comm_free(&node);
    char name[MPI_MAX_PROCESSOR_NAME];
    int length = 0;
    MPI_Get_processor_name(name, &length);
    membership.host.assign(name, size_t(length));
    return new MpiTransport();
}

}  // namespace
}  // namespace fgr

extern "C" __attribute__((visibility("default"))) const fgr::MpiModule* fgr_mpi_module() {
    static const fgr::MpiModule module{fgr::kMpiModuleVersion, fgr::join};
    return &module;
}
