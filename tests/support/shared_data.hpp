#pragma once
// The shared DEMs and meshes beside the checkout (../shared/data, TS_SHARED_DATA).
#include <filesystem>
#include <string>

namespace ts::test {

inline std::string shared_data(const std::string& relative) { return std::string(TS_SHARED_DATA) + "/" + relative; }

// A DEM of the shared data (dem/NAME).
inline std::filesystem::path shared_dem(const std::string& name) { return std::filesystem::path(TS_SHARED_DATA) / "dem" / name; }

// The Cessna 172 of the shared meshes (AC3D, FlightGear's c172p).
inline const std::string kCessna = shared_data("meshes/c172p.ac");

}  // namespace ts::test
