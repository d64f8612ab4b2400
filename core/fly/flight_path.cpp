#include "core/fly/flight_path.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::fly {
namespace {

// At most 24 characters of a field, anything outside printable ASCII as \xNN: a binary file
// must not write its raw bytes to the terminal.
std::string excerpt(const std::string& field) {
    std::string out;
    for (std::size_t i = 0; i < field.size() && i < 24; ++i) {
        const unsigned char c = static_cast<unsigned char>(field[i]);
        if (c >= 0x20 && c < 0x7f && c != '\\') {
            out += char(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    if (field.size() > 24) out += "...";
    return out;
}

double lerp_angle_deg(double a, double b, double f) {
    double d = std::fmod(b - a, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    double v = a + f * d;
    v = std::fmod(v, 360.0);
    return v < 0 ? v + 360.0 : v;
}

}  // namespace

FlightPath::FlightPath(std::vector<FlightPose> poses) : poses_(std::move(poses)) {
    for (std::size_t i = 1; i < poses_.size(); ++i)
        if (!(poses_[i].t_s > poses_[i - 1].t_s))
            throw InputError("flight path: times must increase (t_s " + std::to_string(poses_[i].t_s) + " after " +
                             std::to_string(poses_[i - 1].t_s) + ")");
}

FlightPose FlightPath::at(double t) const {
    if (poses_.empty()) return {};
    if (t <= poses_.front().t_s) return poses_.front();
    if (t >= poses_.back().t_s) return poses_.back();
    std::size_t i = 1;
    while (poses_[i].t_s < t) ++i;
    const FlightPose& a = poses_[i - 1];
    const FlightPose& b = poses_[i];
    const double f = (t - a.t_s) / (b.t_s - a.t_s);
    FlightPose p;
    p.t_s = t;
    p.lon_deg = a.lon_deg + f * (b.lon_deg - a.lon_deg);
    p.lat_deg = a.lat_deg + f * (b.lat_deg - a.lat_deg);
    p.height_m = a.height_m + f * (b.height_m - a.height_m);
    p.heading_deg = lerp_angle_deg(a.heading_deg, b.heading_deg, f);
    p.pitch_deg = a.pitch_deg + f * (b.pitch_deg - a.pitch_deg);
    p.roll_deg = a.roll_deg + f * (b.roll_deg - a.roll_deg);
    return p;
}

FlightPath read_flight_path(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw QuantityError(Quantity::flight_path, path, "cannot open the file");
    std::vector<FlightPose> poses;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (number == 1 && line.find("t_s") != std::string::npos) continue;  // the header
        std::stringstream fields(line);
        double v[7];
        std::string field;
        int n = 0;
        while (std::getline(fields, field, ',')) {
            if (n >= 7) break;
            char* end = nullptr;
            v[n] = std::strtod(field.c_str(), &end);
            while (end != nullptr && (*end == ' ' || *end == '\t')) ++end;
            if (end == field.c_str() || (end != nullptr && *end != '\0') || !std::isfinite(v[n]))
                throw QuantityError(Quantity::flight_path, path + " line " + std::to_string(number),
                                    "'" + excerpt(field) + "' is not a number");
            ++n;
        }
        if (n != 7 || std::getline(fields, field, ','))
            throw QuantityError(Quantity::flight_path, path + " line " + std::to_string(number),
                                "give t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg (7 numbers)");
        if (v[2] < -90 || v[2] > 90)
            throw QuantityError(Quantity::flight_path, path + " line " + std::to_string(number), "latitude must be in [-90, 90]");
        poses.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6]});
    }
    if (poses.empty()) throw QuantityError(Quantity::flight_path, path, "no poses in the file");
    try {
        return FlightPath(std::move(poses));
    } catch (const InputError& e) {
        throw QuantityError(Quantity::flight_path, path, e.what());
    }
}

std::string flight_path_csv(const FlightPath& path) {
    std::string out = "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n";
    char buf[256];
    for (const FlightPose& p : path.poses()) {
        std::snprintf(buf, sizeof buf, "%.3f,%.7f,%.7f,%.2f,%.2f,%.2f,%.2f\n", p.t_s, p.lon_deg, p.lat_deg,
                      p.height_m, p.heading_deg, p.pitch_deg, p.roll_deg);
        out += buf;
    }
    return out;
}

}  // namespace ts::fly
