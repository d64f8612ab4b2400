#pragma once
// terrashade's exit codes, for both executables: 0 done, 1 a bug (an internal error), 2 bad usage
// or input the user can fix (one line on stderr).
namespace ts::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBug = 1;
inline constexpr int kExitBadInput = 2;

}  // namespace ts::app
