#pragma once
// One job per output: while a command runs, each of its outputs (a file, or a folder of tiles or
// frames) is locked, and a second terrashade job on the same output is refused before it
// touches anything, instead of mixing its tiles or frames with the first's. The lock is an
// flock on a small file in the system's temporary folder (terrashade-UID-HASH.lock) named by
// the output's absolute, normalised path, so the user's folders get no lock files; the file
// goes when the job ends or is interrupted, and the kernel drops the lock however the process
// ends (a killed -9 job's file stays, unlocked, and is reused). (Jobs on other machines sharing a network file system are not
// seen: the Slurm shards write one output each, docs/scale.md.)
#include <filesystem>
#include <string>

namespace ts::app {

class OutputLock {
public:
    // Throws ts::InputError naming the output (and the other job's process id) if another
    // process holds it. `what` names the option ("--out").
    OutputLock(const std::filesystem::path& output, const std::string& what);
    ~OutputLock();
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

private:
    std::filesystem::path file_;
    int fd_ = -1;
};

}  // namespace ts::app
