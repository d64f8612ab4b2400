// terrashade: terrain visibility and shading from real DEMs.
#include "app/terrashade_main.hpp"

int main(int argc, char** argv) { return ts::app::terrashade_main(argc, argv); }
