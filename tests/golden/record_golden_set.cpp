// fgr_golden_record FILE [JOBS]: renders the golden set of every scene the built fgr lists and
// writes it to FILE (tests/golden/golden_set.json). Record it before a change that must not change
// what users see, at the commit before it; test_golden_set.cpp renders it again.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "golden_set.hpp"

int main(int argc, char** argv) {
    using namespace fgr::golden;
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: fgr_golden_record FILE.json [JOBS]\n");
        return 2;
    }
    try {
        const std::vector<GoldenCase> cases = golden_cases(listed_scene_ids());
        std::vector<GoldenRecord> records(cases.size());
        const unsigned jobs = argc == 3 ? static_cast<unsigned>(std::atoi(argv[2]))
                                        : std::max(1u, std::thread::hardware_concurrency());
        std::atomic<std::size_t> next{0};
        std::atomic<std::size_t> done{0};
        auto work = [&] {
            for (std::size_t i = next++; i < cases.size(); i = next++) {
                records[i] = {cases[i], observe(cases[i])};
                std::fprintf(stderr, "%zu/%zu %s: exit %d\n", ++done, cases.size(),
                             cases[i].name.c_str(), records[i].observation.exit_code);
            }
        };
        std::vector<std::thread> workers;
        for (unsigned j = 0; j < std::max(1u, jobs); ++j) workers.emplace_back(work);
        for (std::thread& worker : workers) worker.join();
        write_records(argv[1], records);
        std::fprintf(stderr, "wrote %zu cases to %s\n", records.size(), argv[1]);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fgr_golden_record: %s\n", error.what());
        return 1;
    }
    return 0;
}
