// SPDX-License-Identifier: Apache-2.0
#pragma once
// The golden set: every scene in every mode and precision it offers, rendered small by the `fgr`
// command line, with what decides the user's result recorded (exit code, error lines, the
// `--stats` figures but timings, and a hash of the written file). A change that should leave what
// users see unchanged (a refactoring of the host, of the kernel library's layout) renders the set
// again and must reproduce every record exactly.
//
// Float results depend on the OpenCL compiler and the CPU it targets, so the hash and the figures
// are compared only on the device the set was recorded on; elsewhere the exit codes, the error
// lines and which figures are printed still must match.

#include <filesystem>
#include <string>
#include <vector>

namespace fgr::golden {

struct GoldenCase {
    std::string name;               // "mandelbulb_path_double": a gtest parameter name
    std::vector<std::string> args;  // fgr's arguments, the output file "out.png" in its folder
};

struct Observation {
    int exit_code = -1;
    std::string output_hash;           // FNV-1a of the written file, empty when none was written
    std::vector<std::string> figures;  // stdout lines but timings (render_ms, samples_per_second)
    std::vector<std::string> errors;   // the "fgr: error: ..." lines
    std::string device;                // the OpenCL device the kernel was built for
    bool operator==(const Observation&) const = default;
};

struct GoldenRecord {
    GoldenCase golden_case;
    Observation observation;
};

// Width and height of every render: small, so the set's time is the kernels' compilation.
inline constexpr int kGoldenWidth = 40;
inline constexpr int kGoldenHeight = 30;

// Every case of the scenes `ids` names: each scene in the shaded, path and brute modes, in float
// and in double. A mode a scene does not offer is a case too: its error must not change either.
std::vector<GoldenCase> golden_cases(const std::vector<std::string>& ids);

// The scene ids `fgr list --ids` prints, in its order.
std::vector<std::string> listed_scene_ids();

// Runs one case's render in a fresh folder of its own.
Observation observe(const GoldenCase& golden_case);

// The figure's key: "hits" of "hits 1077".
std::string figure_key(const std::string& figure);

void write_records(const std::filesystem::path& file, const std::vector<GoldenRecord>& records);
// Throws std::runtime_error naming the file when it is not a golden set.
std::vector<GoldenRecord> read_records(const std::filesystem::path& file);

}  // namespace fgr::golden
