#include "app/bench/shell_command.hpp"

#include <cstdlib>

namespace ts::app {

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

bool on_path(const std::string& program) {
    return std::system(("command -v " + shell_quote(program) + " > /dev/null 2>&1").c_str()) == 0;
}

}  // namespace ts::app
