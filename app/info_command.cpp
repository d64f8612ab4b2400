// Placeholder replaced by the DEM ingest work (issue 2).
#include "app/command.hpp"
namespace ts::app {
void add_info_command(CLI::App& root) { root.add_subcommand("info", "Describe DEM files"); }
}  // namespace ts::app
