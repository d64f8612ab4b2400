#pragma once
// Numeric flags of every command answer a word with "not a number", in the user's words
// (`terrashade: --directions: 'abc' is not a number`), instead of CLI11's "Value abc not in
// range 1 to 4096"; a number out of range still gets its option's range message.
#include <CLI/CLI.hpp>

namespace ts::app {

// Adds the check to every integer and floating-point option of `app` and its subcommands, in
// front of their own checks. Call once, after every command was added. The check throws
// ts::InputError (one line, exit 2).
void explain_non_numbers(CLI::App& app);

}  // namespace ts::app
