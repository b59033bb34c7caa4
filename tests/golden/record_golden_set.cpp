// SPDX-License-Identifier: Apache-2.0
// fgr_golden_record FILE [JOBS] [SCENE...]: renders the golden set of every scene the built fgr
// lists and writes it to FILE (tests/golden/golden_set.json). Record it before a change that must
// not change what users see, at the commit before it; test_golden_set.cpp renders it again.
// With SCENE ids, only those scenes' cases are rendered again; every other case keeps its record
// from FILE, so a change meant to alter a few scenes' images records just those.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "golden_set.hpp"

namespace {

using namespace fgr::golden;

// The cases to render: all of them, or those of `only` (each of which must be listed).
std::vector<GoldenCase> cases_to_render(const std::vector<std::string>& listed,
                                        const std::vector<std::string>& only) {
    if (only.empty()) return golden_cases(listed);
    for (const std::string& id : only) {
        if (std::find(listed.begin(), listed.end(), id) == listed.end()) {
            throw std::runtime_error("no scene '" + id + "' in fgr list");
        }
    }
    return golden_cases(only);
}

// Every listed case in fgr list's order: the rendered record where there is one, else the one
// FILE holds (which must then have it).
std::vector<GoldenRecord> merged(const std::vector<std::string>& listed,
                                 const std::vector<GoldenRecord>& rendered,
                                 const std::vector<GoldenRecord>& kept) {
    std::map<std::string, const GoldenRecord*> by_name;
    for (const GoldenRecord& record : kept) by_name[record.golden_case.name] = &record;
    for (const GoldenRecord& record : rendered) by_name[record.golden_case.name] = &record;
    std::vector<GoldenRecord> records;
    for (const GoldenCase& golden_case : golden_cases(listed)) {
        const auto found = by_name.find(golden_case.name);
        if (found == by_name.end()) {
            throw std::runtime_error("the set has no case " + golden_case.name +
                                     ": record every scene");
        }
        records.push_back(*found->second);
    }
    return records;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: fgr_golden_record FILE.json [JOBS] [SCENE...]\n");
        return 2;
    }
    try {
        const std::vector<std::string> listed = listed_scene_ids();
        const std::vector<std::string> only(argv + std::min(argc, 3), argv + argc);
        const std::vector<GoldenCase> cases = cases_to_render(listed, only);
        std::vector<GoldenRecord> records(cases.size());
        const unsigned jobs = argc >= 3 ? static_cast<unsigned>(std::atoi(argv[2]))
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
        if (!only.empty()) records = merged(listed, records, read_records(argv[1]));
        write_records(argv[1], records);
        std::fprintf(stderr, "wrote %zu cases to %s\n", records.size(), argv[1]);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fgr_golden_record: %s\n", error.what());
        return 1;
    }
    return 0;
}
