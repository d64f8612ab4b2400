#pragma once
// --size WIDTHxHEIGHT: one parser for every command that takes a picture's size in pixels, each
// command with its own range (render: 1..16384, fly's window and frames: 16..8192).
#include <string>

namespace ts::app {

struct SizeRange {
    int min_side = 1;
    int max_side = 16384;
    const char* example = "1280x720";
};

// Parses TEXT into width and height, or throws ts::InputError naming --size, the range and an example.
void parse_size(const std::string& text, const SizeRange& range, int& width, int& height);

}  // namespace ts::app
