#include "app/bench/grass_session.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "app/bench/shell_command.hpp"
#include "core/util/error.hpp"

namespace ts::app {

GrassSession::GrassSession(const std::filesystem::path& dir, const std::string& crs)
    : dir_(dir), location_(dir / "grass_location") {
    const std::string log = (dir_ / "grass_create.log").string();
    const TimedRun r = run_timed("grass -c " + shell_quote(crs) + " " + shell_quote(location_.string()) + " -e > " +
                                 shell_quote(log) + " 2>&1");
    if (!r.ok) throw InputError("grass: could not create a temporary location; see " + log);
}

GrassSession::~GrassSession() {
    std::error_code ec;
    std::filesystem::remove_all(location_, ec);  // only the location this session created
}

std::map<std::string, TimedRun> GrassSession::run(const std::string& script) {
    const std::filesystem::path script_path = dir_ / "grass_script.sh", times = dir_ / "grass_times.txt",
                                log = dir_ / "grass_script.log", modules_log = dir_ / "grass_modules.log";
    {
        std::ofstream out(script_path, std::ios::binary);
        // bash's `time` keyword times one module and its children, not the session around it.
        out << "set -euo pipefail\nTIMEFORMAT='%R %U %S'\n"
            << "timed() { local label=$1 t; shift; t=$( { time \"$@\" >> " << shell_quote(modules_log.string())
            << " 2>&1 ; } 2>&1 ); echo \"$label $t\" >> " << shell_quote(times.string()) << "; }\n"
            << script;
        if (!out.flush()) throw input_error(script_path.string(), "cannot write");
    }
    std::filesystem::remove(times);
    std::map<std::string, TimedRun> result;
    const TimedRun all = run_timed("grass " + shell_quote((location_ / "PERMANENT").string()) + " --exec bash " +
                                   shell_quote(script_path.string()) + " > " + shell_quote(log.string()) + " 2>&1");
    if (!all.ok) throw InputError("GRASS script failed; see " + log.string() + " and " + modules_log.string());
    result["session"] = all;
    std::map<std::string, std::vector<TimedRun>> runs;
    std::ifstream in(times);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        std::string label;
        double real = 0, user = 0, sys = 0;
        if (f >> label >> real >> user >> sys) runs[label].push_back(TimedRun{true, real, user + sys});
    }
    for (const auto& [label, list] : runs) result[label] = median_run(list);
    return result;
}

}  // namespace ts::app
