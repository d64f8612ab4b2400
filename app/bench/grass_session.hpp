#pragma once
// A throw-away GRASS GIS location for the benchmarks that compare with GRASS modules (r.sun,
// r.horizon): created under a directory the bench made, used through `grass LOC/PERMANENT
// --exec`, removed with everything it holds when the session ends. Nothing of the user's GRASS
// database is touched.
#include <filesystem>
#include <map>
#include <string>

#include "app/bench/timed_shell.hpp"

namespace ts::app {

class GrassSession {
public:
    // Creates the location `dir`/grass_location in `crs` (e.g. "EPSG:4326"); `dir` must exist and
    // belong to the caller. Throws ts::InputError (with the log's path) when grass fails.
    GrassSession(const std::filesystem::path& dir, const std::string& crs);
    ~GrassSession();
    GrassSession(const GrassSession&) = delete;
    GrassSession& operator=(const GrassSession&) = delete;

    // Runs a bash script inside the location. Lines of the script may time a module each with
    // `timed LABEL module args...` (a function defined here): each module's own wall and CPU
    // seconds, without the session's start-up, are returned by label (the median of the runs
    // when a label is timed more than once). The whole run's time is under the label "session". Throws ts::InputError naming the log when the script fails.
    std::map<std::string, TimedRun> run(const std::string& script);

private:
    std::filesystem::path dir_, location_;
};

}  // namespace ts::app
