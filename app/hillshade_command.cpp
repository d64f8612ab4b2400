// Placeholder replaced by the hillshade work (issue 2).
#include "app/command.hpp"
namespace ts::app {
void add_hillshade_command(CLI::App& root) { root.add_subcommand("hillshade", "Classic Horn hillshade"); }
}  // namespace ts::app
