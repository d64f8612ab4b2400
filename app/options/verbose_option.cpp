#include "app/options/verbose_option.hpp"

namespace ts::app {

void add_verbose_flag(CLI::App& cmd, bool& verbose, const std::string& what) {
    cmd.add_flag("-v,--verbose", verbose, "Say what was chosen and why: " + what);
}

}  // namespace ts::app
