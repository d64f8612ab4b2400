#include "app/options/directions_option.hpp"

#include <string>
#include "app/options/within_range.hpp"

namespace ts::app {

CLI::Option* add_directions_option(CLI::App& cmd, int& directions, bool* given) {
    CLI::Option* o = cmd.add_option("--directions", directions,
                                    "Horizon azimuths of the sky visibility, " + std::to_string(kMinDirections) +
                                        ".." + std::to_string(kMaxDirections) + " (more: finer sky shadows, slower)")
                         ->capture_default_str()
                         ->check(within(kMinDirections, kMaxDirections));
    if (given) o->each([given](const std::string&) { *given = true; });
    return o;
}

}  // namespace ts::app
