// SPDX-License-Identifier: Apache-2.0
#pragma once
// An environment variable set (or unset) for one scope, and restored to what it was when the
// scope ends.

#include <cstdlib>
#include <optional>
#include <string>

namespace fgr::test {

class ScopedEnv {
public:
    // `value` nullptr unsets the variable.
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_value_ = old;
        set(value);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;
    ~ScopedEnv() { set(old_value_ ? old_value_->c_str() : nullptr); }

    // Sets the variable again, or unsets it, within the scope.
    void set(const char* value) {
        if (value != nullptr) {
            ::setenv(name_.c_str(), value, 1);
        } else {
            ::unsetenv(name_.c_str());
        }
    }

private:
    std::string name_;
    std::optional<std::string> old_value_;
};

}  // namespace fgr::test
