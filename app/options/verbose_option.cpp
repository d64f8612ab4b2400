#include "app/options/verbose_option.hpp"

namespace ts::app {

void add_verbose_flag(CLI::App& cmd, bool& verbose) {
    cmd.add_flag("-v,--verbose", verbose,
                 "Say what was chosen and why, of what the command has: the device and where each stage ran, the "
                 "sun and each zoom's DEM level (tiles), a mesh's assumed forward axis");
}

}  // namespace ts::app
