#pragma once
// The flag each command takes for a quantity core/ names (core/util/quantity_error.hpp): core
// says "number of directions: must be ...", the user reads "--directions: must be ...".
#include <string>
#include <string_view>

#include "core/util/quantity_error.hpp"

namespace ts::app {

// The flag `command` ("render", "bench transfer", ...) takes for `quantity`.
std::string_view flag_of(Quantity quantity, std::string_view command);

// e's message with the flag of `command` in place of the quantity's words.
std::string flag_message(const QuantityError& e, std::string_view command);

// e's message with the flags that resolve it: "give --overwrite to replace ..., or --out another
// folder" (and "drop --resume" when resuming).
std::string flag_message(const OccupiedOutputError& e);

}  // namespace ts::app
