#pragma once
// The reason an errno value stands for, in the words a failure message gives it.

#include <string>
#include <system_error>

namespace fgr {

// "No such file or directory" for ENOENT: the C library's text of a POSIX error number.
inline std::string errno_message(int error) { return std::generic_category().message(error); }

}  // namespace fgr
