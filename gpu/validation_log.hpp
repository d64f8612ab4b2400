#pragma once
// Where the debug messenger puts what the validation layer says. Tests enable validation and
// fail if the log is not empty; the command line echoes each message to stderr.
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace ts::gpu {

class ValidationLog {
public:
    explicit ValidationLog(bool echo_to_stderr = true) : echo_(echo_to_stderr) {}

    // Called from the layer's callback, possibly on several threads at once.
    void add(std::string message);

    std::vector<std::string> messages() const;
    std::size_t size() const;
    bool empty() const { return size() == 0; }

private:
    bool echo_;
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

}  // namespace ts::gpu
