#pragma once
// Errors that reach the user as one line on stderr and exit code 2 (bad usage or bad input).
// Anything else escaping to main is a bug and exits 1.
#include <stdexcept>
#include <string>

namespace ts {

// Bad input: a missing, truncated, mislabelled or unsupported file, or an absurd option.
// what() is the whole message the user sees; name the file and the problem.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "path: problem", the one format every input error uses.
inline InputError input_error(const std::string& path, const std::string& problem) {
    return InputError(path + ": " + problem);
}

}  // namespace ts
