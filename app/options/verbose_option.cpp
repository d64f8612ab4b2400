#include "app/options/verbose_option.hpp"

namespace ts::app {

void add_verbose_flag(CLI::App& cmd, bool& verbose) {
    cmd.add_flag("-v,--verbose", verbose,
                 "Say what was chosen and why: the device and where each stage ran, a mesh's assumed forward axis");
}

}  // namespace ts::app
