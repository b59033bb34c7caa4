// SPDX-License-Identifier: Apache-2.0
#include "distributed/cluster.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <thread>

#include "distributed/transport.hpp"

namespace fgr {
namespace {

// The header of every message; the payload follows.
struct Header {
    int32_t kind;
    int32_t reserved;
    int64_t task;
};

std::unique_ptr<Transport>& transport_storage() {
    static std::unique_ptr<Transport> transport;
    return transport;
}

int environment_int(std::initializer_list<const char*> names, int fallback) {
    for (const char* name : names) {
        if (const char* value = std::getenv(name); value && *value) return std::atoi(value);
    }
    return fallback;
}

std::string this_host() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name;
}

}  // namespace

// Open MPI's mpirun, MPICH's and Intel's hydra (PMI), and PMIx launchers such as Slurm's srun.
int launcher_world_size() {
    return environment_int({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"}, 1);
}

int launcher_world_rank() {
    return environment_int({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}, 0);
}

Cluster& Cluster::current() {
    static Cluster cluster;
    return cluster;
}

Cluster& Cluster::join(int* argc, char*** argv) {
    Cluster& cluster = current();
    Membership membership;
    membership.host = this_host();
    transport_storage() = join_transport(argc, argv, membership);
    cluster.transport_ = transport_storage().get();
    cluster.rank_ = membership.rank;
    cluster.size_ = cluster.transport_ ? membership.size : 1;
    cluster.local_rank_ = membership.local_rank;
    cluster.host_ = membership.host;
    cluster.unavailable_ = membership.unavailable;
    cluster.finished_.assign(size_t(cluster.size_), false);
    cluster.owed_reply_.assign(size_t(cluster.size_), false);
    cluster.peers_.assign(size_t(cluster.size_), {});
    return cluster;
}

std::string Cluster::name() const { return fmt::format("rank {} ({})", rank_, host_); }

void Cluster::send(int to, MessageKind kind, int64_t task, std::span<const uint8_t> payload) {
    if (!transport_) throw std::logic_error("a cluster of one process sends no messages");
    std::vector<uint8_t> bytes(sizeof(Header) + payload.size());
    const Header header{static_cast<int32_t>(kind), 0, task};
    std::memcpy(bytes.data(), &header, sizeof header);
    if (!payload.empty()) std::memcpy(bytes.data() + sizeof header, payload.data(), payload.size());
    transport_->send(to, bytes);
    traffic_.messages += 1;
    traffic_.bytes += long(bytes.size());
    if (coordinator()) {
        owed_reply_[size_t(to)] = false;
        if (kind == MessageKind::Done) finished_[size_t(to)] = true;
    }
}

std::optional<Message> Cluster::try_receive(int from) {
    if (!transport_) throw std::logic_error("a cluster of one process receives no messages");
    auto arrived = transport_->try_receive(from);
    if (!arrived) return std::nullopt;
    auto& [sender, bytes] = *arrived;
    if (bytes.size() < sizeof(Header)) {
        throw std::runtime_error(
            fmt::format("a message of {} bytes from rank {} is too short", bytes.size(), sender));
    }
    Header header{};
    std::memcpy(&header, bytes.data(), sizeof header);
    Message message;
    message.from = sender;
    message.kind = static_cast<MessageKind>(header.kind);
    message.task = header.task;
    message.payload.assign(bytes.begin() + sizeof header, bytes.end());
    traffic_.messages += 1;
    traffic_.bytes += long(bytes.size());
    if (coordinator()) {
        if (message.kind == MessageKind::Failure) finished_[size_t(sender)] = true;
        if (message.kind == MessageKind::Ready && sender > 0 && sender < size_) {
            // "PID HOST" (ready_payload); anything else leaves the worker unwatched.
            const std::string text(message.payload.begin(), message.payload.end());
            const size_t space = text.find(' ');
            if (space != std::string::npos && space > 0 && space < 12) {
                peers_[size_t(sender)] = {std::atol(text.c_str()), text.substr(space + 1)};
            }
        }
        // A worker that asked waits for the answer; if rank 0 fails before giving it,
        // dismiss_workers does.
        owed_reply_[size_t(sender)] =
            message.kind == MessageKind::Ready || message.kind == MessageKind::Result;
    }
    return message;
}

Message Cluster::receive(int from) {
    // Tiles and frames take milliseconds to seconds: a 0.2 ms nap costs nothing measurable and
    // leaves the core to the renderer.
    while (true) {
        if (std::optional<Message> message = try_receive(from)) return std::move(*message);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

bool Cluster::worker_active(int rank) const {
    return rank > 0 && rank < size_ && !finished_[size_t(rank)];
}

std::string Cluster::dismiss_workers() {
    std::string failure;
    if (!coordinator() || alone()) return failure;
    const auto any_active = [this] {
        for (int r = 1; r < size_; ++r) {
            if (worker_active(r)) return true;
        }
        return false;
    };
    for (int r = 1; r < size_; ++r) {
        if (worker_active(r) && owed_reply_[size_t(r)]) send(r, MessageKind::Done, -1);
    }
    while (any_active()) {
        std::optional<Message> arrived = try_receive();
        if (!arrived) {
            vanished_worker();  // a worker whose process is gone owes no message
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        const Message& message = *arrived;
        if (message.kind == MessageKind::Failure) {
            if (failure.empty())
                failure = std::string(message.payload.begin(), message.payload.end());
        } else if (worker_active(message.from)) {
            send(message.from, MessageKind::Done, -1);
        }
    }
    return failure;
}

void Cluster::report_failure(const std::string& message) {
    if (coordinator() || alone() || failure_reported_) return;
    failure_reported_ = true;
    const std::string text = name() + ": " + message;
    send(0, MessageKind::Failure, -1,
         std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

std::vector<uint8_t> Cluster::ready_payload() const {
    const std::string text = fmt::format("{} {}", long(::getpid()), host_);
    return {text.begin(), text.end()};
}

std::optional<std::string> Cluster::vanished_worker() {
    for (int r = 1; r < size_; ++r) {
        const Peer& peer = peers_[size_t(r)];
        if (!worker_active(r) || peer.pid <= 0 || peer.host != host_) continue;
        if (::kill(static_cast<pid_t>(peer.pid), 0) == 0 || errno != ESRCH) continue;
        finished_[size_t(r)] = true;  // no answer is owed to a process that is gone
        return fmt::format("rank {} ({})", r, peer.host);
    }
    return std::nullopt;
}

void Cluster::leave() {
    if (transport_) transport_->finalize();
    transport_storage().reset();
    transport_ = nullptr;
    size_ = 1;
}

}  // namespace fgr
