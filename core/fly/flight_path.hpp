#pragma once
// A flight path: poses at times, read from and written to CSV with the header
//   t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg
// (seconds from the start, degrees WGS84, metres above the DEM's datum, heading clockwise from
// north, pitch nose up, roll right wing down). Between samples every field is interpolated
// linearly, angles the short way round; before the first and after the last sample the end
// pose holds.
#include <string>
#include <vector>

namespace ts::fly {

struct FlightPose {
    double t_s = 0, lon_deg = 0, lat_deg = 0, height_m = 0;
    double heading_deg = 0, pitch_deg = 0, roll_deg = 0;
};

class FlightPath {
public:
    FlightPath() = default;
    // Times must increase strictly. Throws ts::InputError otherwise.
    explicit FlightPath(std::vector<FlightPose> poses);

    bool empty() const { return poses_.empty(); }
    const std::vector<FlightPose>& poses() const { return poses_; }
    double start_s() const { return poses_.empty() ? 0.0 : poses_.front().t_s; }
    double duration_s() const { return poses_.empty() ? 0.0 : poses_.back().t_s - poses_.front().t_s; }
    FlightPose at(double t_s) const;

private:
    std::vector<FlightPose> poses_;
};

// Throws ts::InputError with the file name and line for a bad file (one line).
FlightPath read_flight_path(const std::string& path);
// The CSV text of a path (what recording writes).
std::string flight_path_csv(const FlightPath& path);

}  // namespace ts::fly
