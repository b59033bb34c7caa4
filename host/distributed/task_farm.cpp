// SPDX-License-Identifier: Apache-2.0
#include "distributed/task_farm.hpp"

#include <fmt/format.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string_view>
#include <thread>
#include <unordered_map>

#include "util/interruption.hpp"

namespace fgr {
namespace {

// Rank 0's own renderer: one task at a time on a thread of its own, so that the main thread stays
// free to answer the other ranks and to write.
class LocalWorker {
public:
    explicit LocalWorker(const TaskWork& work) : work_(work), thread_([this] { loop(); }) {}
    ~LocalWorker() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();  // after the task in hand, if any
    }
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    bool idle() {
        std::lock_guard lock(mutex_);
        return !task_ && !result_ && !error_;
    }
    void assign(int64_t task) {
        {
            std::lock_guard lock(mutex_);
            task_ = task;
        }
        wake_.notify_all();
    }
    // The finished task and its result; rethrows what the task threw.
    std::optional<std::pair<int64_t, std::vector<uint8_t>>> take_finished() {
        std::lock_guard lock(mutex_);
        if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
        if (!result_) return std::nullopt;
        return std::exchange(result_, std::nullopt);
    }

private:
    void loop() {
        std::unique_lock lock(mutex_);
        while (true) {
            wake_.wait(lock, [this] { return stop_ || (task_ && !result_); });
            if (stop_) return;
            const int64_t task = *task_;
            lock.unlock();
            std::vector<uint8_t> bytes;
            std::exception_ptr error;
            try {
                bytes = work_(task);
            } catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            task_.reset();
            if (error) {
                error_ = error;
            } else {
                result_ = std::make_pair(task, std::move(bytes));
            }
        }
    }

    const TaskWork& work_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<int64_t> task_;
    std::optional<std::pair<int64_t, std::vector<uint8_t>>> result_;
    std::exception_ptr error_;
    bool stop_ = false;
    std::thread thread_;
};

void run_worker(Cluster& cluster, const TaskWork& work) {
    cluster.send(0, MessageKind::Ready, -1, cluster.ready_payload());
    while (true) {
        const Message message = cluster.receive(0);
        if (message.kind == MessageKind::Done) return;
        if (message.kind != MessageKind::Task) {
            throw std::runtime_error(
                fmt::format("unexpected message {} from rank 0", static_cast<int>(message.kind)));
        }
        const std::vector<uint8_t> result = work(message.task);
        cluster.send(0, MessageKind::Result, message.task, result);
        hold_for_test("task");
    }
}

// Rank 0's bookkeeping: which tasks went out, which came back, who waits for one.
class Schedule {
public:
    Schedule(const std::vector<int64_t>& tasks, int window)
        : tasks_(tasks), window_(size_t(window)), done_(tasks.size()) {
        for (size_t i = 0; i < tasks.size(); ++i) position_[tasks[i]] = i;
    }
    bool all_handed_out() const { return next_ >= tasks_.size(); }
    bool all_back() const { return back_ == tasks_.size(); }
    // The next task, unless the window holds it back (or none is left).
    std::optional<int64_t> hand_out() {
        if (all_handed_out() || next_ >= oldest_ + window_) return std::nullopt;
        return tasks_[next_++];
    }
    void returned(int64_t task) {
        const auto it = position_.find(task);
        if (it == position_.end() || it->second >= next_ || done_[it->second]) {
            throw std::runtime_error(fmt::format("task {} came back but was not out", task));
        }
        done_[it->second] = true;
        ++back_;
        while (oldest_ < done_.size() && done_[oldest_]) ++oldest_;
    }

private:
    const std::vector<int64_t>& tasks_;
    size_t window_;
    std::vector<bool> done_;
    std::unordered_map<int64_t, size_t> position_;
    size_t next_ = 0, oldest_ = 0, back_ = 0;
};

FarmOutcome run_coordinator(Cluster& cluster, const std::vector<int64_t>& tasks,
                            const TaskWork& work, const ResultSink& sink,
                            const FarmSettings& settings) {
    FarmOutcome outcome;
    outcome.tasks_by_rank.assign(size_t(cluster.size()), 0);
    const int window = settings.window > 0 ? settings.window : 4 * cluster.size();
    Schedule schedule(tasks, window);
    std::deque<int> waiting;  // workers that asked while the window was full
    // Gives `rank` its next task, Done when none is left, or keeps it waiting.
    const auto serve = [&](int rank) {
        if (schedule.all_handed_out()) {
            cluster.send(rank, MessageKind::Done, -1);
        } else if (const std::optional<int64_t> task = schedule.hand_out()) {
            cluster.send(rank, MessageKind::Task, *task);
        } else {
            waiting.push_back(rank);
        }
    };
    const auto serve_waiting = [&] {
        for (size_t n = waiting.size(); n > 0 && !waiting.empty(); --n) {
            const int rank = waiting.front();
            waiting.pop_front();
            serve(rank);
        }
    };
    LocalWorker local(work);
    // A worker killed outright says nothing, and mpirun then stops the whole job (rank 0 with
    // SIGTERM): rank 0 looks for such a worker now and then, and when it is stopped, so that the
    // job ends naming the rank that died rather than only as interrupted.
    const auto check_workers = [&] {
        if (const std::optional<std::string> rank = cluster.vanished_worker()) {
            throw RankLost(*rank + ": its process ended without a word (killed, or crashed)");
        }
    };
    auto last_check = std::chrono::steady_clock::now();
    while (!schedule.all_back()) {
        if (settings.interrupted && settings.interrupted()) {
            check_workers();
            return outcome;
        }
        if (std::chrono::steady_clock::now() - last_check > std::chrono::milliseconds(50)) {
            check_workers();
            last_check = std::chrono::steady_clock::now();
        }
        bool busy = false;
        while (std::optional<Message> message = cluster.try_receive()) {
            busy = true;
            switch (message->kind) {
                case MessageKind::Ready:
                    serve(message->from);
                    break;
                case MessageKind::Result:
                    schedule.returned(message->task);
                    ++outcome.tasks_by_rank[size_t(message->from)];
                    sink(message->task, std::move(message->payload));
                    serve_waiting();
                    serve(message->from);
                    break;
                case MessageKind::Failure:
                    throw RankFailure(
                        std::string(message->payload.begin(), message->payload.end()));
                default:
                    throw std::runtime_error(fmt::format("unexpected message {} from rank {}",
                                                         static_cast<int>(message->kind),
                                                         message->from));
            }
        }
        if (auto finished = local.take_finished()) {
            busy = true;
            schedule.returned(finished->first);
            ++outcome.tasks_by_rank[0];
            sink(finished->first, std::move(finished->second));
            serve_waiting();
        }
        if (settings.coordinator_renders && local.idle()) {
            if (const std::optional<int64_t> task = schedule.hand_out()) {
                local.assign(*task);
                busy = true;
            }
        }
        if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    // Workers still waiting for a task learn there is none.
    for (int rank : waiting) cluster.send(rank, MessageKind::Done, -1);
    outcome.finished = true;
    return outcome;
}

FarmOutcome run_alone(const std::vector<int64_t>& tasks, const TaskWork& work,
                      const ResultSink& sink, const FarmSettings& settings) {
    FarmOutcome outcome;
    outcome.tasks_by_rank = {0};
    for (int64_t task : tasks) {
        if (settings.interrupted && settings.interrupted()) return outcome;
        sink(task, work(task));
        ++outcome.tasks_by_rank[0];
    }
    outcome.finished = true;
    return outcome;
}

}  // namespace

bool FarmSettings::coordinator_renders_by_default() {
    const char* value = std::getenv("FGR_MPI_RANK0_RENDERS");
    return !(value && std::string_view(value) == "0");
}

void InTaskOrder::add(int64_t task, std::vector<uint8_t>&& result) {
    if (task < expected_ || !early_.emplace(task, std::move(result)).second) {
        throw std::logic_error(fmt::format("task {} arrived twice", task));
    }
    for (auto it = early_.find(expected_); it != early_.end(); it = early_.find(++expected_)) {
        next_(it->first, std::move(it->second));
        early_.erase(it);
    }
}

std::string tasks_by_rank_text(const FarmOutcome& outcome) {
    std::string text;
    for (size_t rank = 0; rank < outcome.tasks_by_rank.size(); ++rank) {
        text += fmt::format("{}{}:{}", text.empty() ? "" : " ", rank, outcome.tasks_by_rank[rank]);
    }
    return text;
}

FarmOutcome run_farm(Cluster& cluster, const std::vector<int64_t>& tasks, const TaskWork& work,
                     const ResultSink& sink, const FarmSettings& settings) {
    if (cluster.alone()) return run_alone(tasks, work, sink, settings);
    if (!cluster.coordinator()) {
        run_worker(cluster, work);
        return {true, {}};
    }
    return run_coordinator(cluster, tasks, work, sink, settings);
}

}  // namespace fgr
