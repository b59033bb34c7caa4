// SPDX-License-Identifier: Apache-2.0
#pragma once
// The default logger's warnings, copied into a string while a LogCapture lives: what a test checks
// fgr told the user.

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fgr::test {

class LogCapture {
public:
    LogCapture()
        : logger_(spdlog::default_logger()),
          sink_(std::make_shared<spdlog::sinks::ostream_sink_mt>(stream_)),
          old_level_(logger_->level()) {
        sink_->set_pattern("%l %v");
        sink_->set_level(spdlog::level::warn);
        logger_->sinks().push_back(sink_);
        if (old_level_ > spdlog::level::warn) logger_->set_level(spdlog::level::warn);
    }
    LogCapture(const LogCapture&) = delete;
    LogCapture& operator=(const LogCapture&) = delete;
    ~LogCapture() {
        auto& sinks = logger_->sinks();
        sinks.erase(std::remove(sinks.begin(), sinks.end(), sink_), sinks.end());
        logger_->set_level(old_level_);
    }

    // The captured lines ("warning ...", "error ..."), in order.
    std::vector<std::string> lines() const {
        std::vector<std::string> found;
        std::istringstream in(stream_.str());
        for (std::string line; std::getline(in, line);) found.push_back(line);
        return found;
    }

private:
    std::ostringstream stream_;
    std::shared_ptr<spdlog::logger> logger_;
    std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink_;
    spdlog::level::level_enum old_level_;
};

}  // namespace fgr::test
