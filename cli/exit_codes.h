// Exit codes of the locus executable (documented in docs/user-guide.md).
#pragma once

namespace locus::cli {

inline constexpr int exit_ok = 0;
inline constexpr int exit_no = 1;            // a yes/no question answered "no" (like grep)
inline constexpr int exit_input = 2;         // bad input: parse error, unknown order, bad option
inline constexpr int exit_timeout = 3;       // --timeout passed
inline constexpr int exit_check_failed = 4;  // --check (or verification) found the result wrong
inline constexpr int exit_resource = 5;   // a resource limit: memory, a size limit, a failed write
inline constexpr int exit_internal = 70;  // an internal error (a bug; please report it)

}  // namespace locus::cli
