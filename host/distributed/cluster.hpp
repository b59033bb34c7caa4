// SPDX-License-Identifier: Apache-2.0
#pragma once
// The processes of one fgr job: the ranks of an MPI job when mpirun started fgr (and fgr was
// built with MPI), or this process alone. Rank 0 coordinates: it hands out work, gathers the
// results, writes the files and prints; the other ranks (workers) render what they are given and
// stay quiet.
//
// The messages are few and small (a task number one way, a tile or a frame back), so they go as
// single point-to-point messages; receiving polls with short sleeps instead of blocking in MPI,
// which would spin a core that the renderer on the same node needs.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fgr {

enum class MessageKind : int32_t {
    Ready = 1,    // worker -> 0: set up, give me a task
    Task = 2,     // 0 -> worker: render task `task`
    Result = 3,   // worker -> 0: task `task`'s result (payload); give me the next
    Failure = 4,  // worker -> 0: this rank failed (payload: the message); it has stopped
    Done = 5,     // 0 -> worker: no more tasks, stop
};

struct Message {
    int from = 0;
    MessageKind kind = MessageKind::Ready;
    int64_t task = -1;
    std::vector<uint8_t> payload;
};

// What rank 0 sent and received: the overhead figures of a distributed render.
struct Traffic {
    long messages = 0;
    long bytes = 0;
};

class Transport;

class Cluster {
public:
    static constexpr int kAnyRank = -1;

    // The job this process belongs to: joins MPI (MPI_Init) when launched by mpirun with more
    // than one rank, else a cluster of this process alone. Call once, before anything else runs;
    // leave() ends it.
    static Cluster& join(int* argc, char*** argv);
    static Cluster& current();  // after join(); alone before

    int rank() const { return rank_; }
    int size() const { return size_; }
    // This rank's number among the ranks on its node (picks its GPU), and the node's name.
    int local_rank() const { return local_rank_; }
    const std::string& host() const { return host_; }
    bool coordinator() const { return rank_ == 0; }
    bool alone() const { return size_ == 1; }
    // "rank 2 (node7)": how messages name this rank.
    std::string name() const;

    void send(int to, MessageKind kind, int64_t task, std::span<const uint8_t> payload = {});
    // The next message (from `from`, or any rank), if one has arrived.
    std::optional<Message> try_receive(int from = kAnyRank);
    // The next message, waiting for it (short sleeps, no spinning).
    Message receive(int from = kAnyRank);

    // Rank 0: whether worker `rank` still owes a message (it has not been sent Done, nor has it
    // failed). The farm and dismiss_workers keep it.
    bool worker_active(int rank) const;
    void mark_finished(int rank);
    // Rank 0, at the end of a command, however it ended: answers every active worker's next
    // message with Done, so no rank is left waiting. Returns the first failure a worker reported
    // meanwhile (empty if none).
    std::string dismiss_workers();
    // A worker that failed: tells rank 0 (which prints it, naming this rank) and stops.
    void report_failure(const std::string& message);

    // A worker's first message (Ready) carries its process id and node (ready_payload); rank 0
    // keeps them. Rank 0: an active worker on rank 0's own node whose process is gone (killed,
    // crashed: it said nothing) is marked finished and named, "rank 1 (node7)"; nullopt when
    // there is none. Workers on other nodes cannot be seen this way (mpirun names them).
    std::vector<uint8_t> ready_payload() const;
    std::optional<std::string> vanished_worker();

    const Traffic& traffic() const { return traffic_; }

    // Ends the MPI job (MPI_Finalize); the cluster is alone after.
    void leave();

    // Why this process cannot take part although a launcher started several ranks (fgr built
    // without MPI); empty when it can.
    const std::string& unavailable() const { return unavailable_; }

private:
    Cluster() = default;
    int rank_ = 0;
    int size_ = 1;
    int local_rank_ = 0;
    std::string host_;
    std::vector<bool> finished_;    // rank 0: per worker
    std::vector<bool> owed_reply_;  // rank 0: the worker asked and waits for an answer
    struct Peer {
        long pid = 0;
        std::string host;
    };
    std::vector<Peer> peers_;  // rank 0: what each worker's Ready said
    bool failure_reported_ = false;
    Traffic traffic_;
    std::string unavailable_;
    Transport* transport_ = nullptr;
};

// Whether the environment says mpirun (Open MPI, MPICH, or a PMI launcher like srun) started this
// process, and as how many ranks (1 when not).
int launcher_world_size();
int launcher_world_rank();

// Owns the join and the leave, for main().
class ClusterSession {
public:
    ClusterSession(int* argc, char*** argv) : cluster_(Cluster::join(argc, argv)) {}
    ~ClusterSession() { cluster_.leave(); }
    ClusterSession(const ClusterSession&) = delete;
    ClusterSession& operator=(const ClusterSession&) = delete;
    Cluster& cluster() { return cluster_; }

private:
    Cluster& cluster_;
};

}  // namespace fgr
