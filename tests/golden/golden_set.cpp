// SPDX-License-Identifier: Apache-2.0
#include "golden_set.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "child_process.hpp"
#include "image/embedded_view.hpp"
#include "util/content_hash.hpp"

namespace fgr::golden {
namespace {
namespace fs = std::filesystem;

const char* const kModes[] = {"shaded", "path", "brute"};
const char* const kPrecisions[] = {"float", "double"};
constexpr int kFormatVersion = 1;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool starts_with(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

// Figures that measure the machine, not the image.
bool is_timing(const std::string& key) {
    return key == "samples_per_second" || key.ends_with("_ms");
}

std::string gtest_name(std::string text) {
    for (char& c : text) {
        if (c == '-') c = '_';
    }
    return text;
}

// "fgr: info: building 'menger' for pthread-skylake-avx512-AMD EPYC (shaded mode, ...": the
// device's name.
std::string built_for(const std::vector<std::string>& err_lines) {
    const std::string marker = " for ";
    for (const std::string& line : err_lines) {
        if (!starts_with(line, "fgr: info: building '")) continue;
        const std::size_t from = line.find(marker);
        const std::size_t to = line.rfind(" (");
        if (from != std::string::npos && to != std::string::npos && to > from) {
            return line.substr(from + marker.size(), to - from - marker.size());
        }
    }
    return "";
}

}  // namespace

std::vector<GoldenCase> golden_cases(const std::vector<std::string>& ids) {
    std::vector<GoldenCase> cases;
    for (const std::string& id : ids) {
        for (const char* mode : kModes) {
            for (const char* precision : kPrecisions) {
                cases.push_back(
                    {gtest_name(id + "_" + mode + "_" + precision),
                     {"render", id, "-o", "out.png", "--width", std::to_string(kGoldenWidth),
                      "--height", std::to_string(kGoldenHeight), "--mode", mode, "--precision",
                      precision, "--stats"}});
            }
        }
    }
    return cases;
}

std::vector<std::string> listed_scene_ids() {
    const test::TempDir folder("fgr_golden_list");
    const test::RunResult listed = test::run_fgr({"list", "--ids"}, folder.path());
    if (!listed.exited || listed.exit_code != 0) {
        throw std::runtime_error("fgr list --ids failed: " + listed.err);
    }
    std::vector<std::string> ids;
    for (const std::string& line : lines_of(listed.out)) {
        if (!line.empty()) ids.push_back(line);
    }
    return ids;
}

// The PNG's bytes without the view it carries (an iTXt chunk "fgr:view"): the view names the
// schema by the path of the tree that wrote it and fgr's version, which are no part of the image.
// A file that is not a well-formed PNG is hashed whole.
std::string png_without_view(const std::string& bytes) {
    constexpr std::size_t kSignature = 8, kChunkFrame = 12;
    std::string kept = bytes.substr(0, std::min(bytes.size(), kSignature));
    std::size_t at = kSignature;
    while (at + kChunkFrame <= bytes.size()) {
        const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
        const std::size_t length = (std::size_t(byte(at)) << 24) |
                                   (std::size_t(byte(at + 1)) << 16) |
                                   (std::size_t(byte(at + 2)) << 8) | std::size_t(byte(at + 3));
        if (length > bytes.size() - at - kChunkFrame) return bytes;
        const std::string type = bytes.substr(at + 4, 4);
        const std::string keyword = std::string(kPngViewKeyword) + '\0';
        const bool view = type == "iTXt" && bytes.compare(at + 8, keyword.size(), keyword) == 0;
        if (!view) kept += bytes.substr(at, length + kChunkFrame);
        at += length + kChunkFrame;
    }
    return at == bytes.size() ? kept : bytes;
}

Observation observe(const GoldenCase& golden_case) {
    const test::TempDir folder("fgr_golden");
    const test::RunResult run = test::run_fgr(golden_case.args, folder.path());
    Observation observation;
    observation.exit_code = run.exited ? run.exit_code : 128 + run.term_signal;
    const fs::path output = folder.path() / "out.png";
    if (fs::exists(output))
        observation.output_hash =
            ContentHash().add(png_without_view(test::read_file(output))).hex();
    for (const std::string& line : lines_of(run.out)) {
        if (!is_timing(figure_key(line))) observation.figures.push_back(line);
    }
    const std::vector<std::string> err_lines = lines_of(run.err);
    for (const std::string& line : err_lines) {
        if (starts_with(line, "fgr: error: ")) observation.errors.push_back(line);
    }
    observation.device = built_for(err_lines);
    return observation;
}

std::string figure_key(const std::string& figure) { return figure.substr(0, figure.find(' ')); }

void write_records(const fs::path& file, const std::vector<GoldenRecord>& records) {
    nlohmann::ordered_json cases = nlohmann::ordered_json::array();
    for (const GoldenRecord& record : records) {
        const Observation& seen = record.observation;
        cases.push_back({{"name", record.golden_case.name},
                         {"args", record.golden_case.args},
                         {"exit_code", seen.exit_code},
                         {"output_hash", seen.output_hash},
                         {"figures", seen.figures},
                         {"errors", seen.errors},
                         {"device", seen.device}});
    }
    const nlohmann::ordered_json set = {
        {"format", "fgr golden set"}, {"version", kFormatVersion}, {"cases", cases}};
    const fs::path temporary = file.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << set.dump(1) << '\n';
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    }
    fs::rename(temporary, file);
}

std::vector<GoldenRecord> read_records(const fs::path& file) {
    try {
        const nlohmann::json set = nlohmann::json::parse(test::read_file(file));
        if (set.at("format") != "fgr golden set" || set.at("version") != kFormatVersion) {
            throw std::runtime_error("not a golden set of version " +
                                     std::to_string(kFormatVersion));
        }
        std::vector<GoldenRecord> records;
        for (const nlohmann::json& entry : set.at("cases")) {
            GoldenRecord record;
            record.golden_case.name = entry.at("name").get<std::string>();
            record.golden_case.args = entry.at("args").get<std::vector<std::string>>();
            Observation& seen = record.observation;
            seen.exit_code = entry.at("exit_code").get<int>();
            seen.output_hash = entry.at("output_hash").get<std::string>();
            seen.figures = entry.at("figures").get<std::vector<std::string>>();
            seen.errors = entry.at("errors").get<std::vector<std::string>>();
            seen.device = entry.at("device").get<std::string>();
            records.push_back(std::move(record));
        }
        return records;
    } catch (const std::exception& error) {
        throw std::runtime_error(file.string() + ": " + error.what());
    }
}

}  // namespace fgr::golden
