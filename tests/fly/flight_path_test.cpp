#include "core/fly/flight_path.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/util/error.hpp"

namespace ts::fly {
namespace {

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
    const auto p = std::filesystem::temp_directory_path() / name;
    std::ofstream(p) << text;
    return p;
}

TEST(FlightPath, InterpolatesFieldsAndHeadingTheShortWay) {
    const FlightPath p({{0, 5.0, 45.0, 1000, 350, 0, 0}, {10, 5.1, 45.2, 2000, 10, 10, -20}});
    const FlightPose m = p.at(5.0);
    EXPECT_NEAR(m.lon_deg, 5.05, 1e-12);
    EXPECT_NEAR(m.lat_deg, 45.1, 1e-12);
    EXPECT_NEAR(m.height_m, 1500, 1e-9);
    EXPECT_NEAR(m.heading_deg, 0.0, 1e-9);  // 350 -> 10 passes through north
    EXPECT_NEAR(m.pitch_deg, 5, 1e-12);
    EXPECT_NEAR(m.roll_deg, -10, 1e-12);
    EXPECT_EQ(p.at(-1).height_m, 1000);  // held before the start
    EXPECT_EQ(p.at(99).height_m, 2000);  // and after the end
}

TEST(FlightPath, CsvRoundTrips) {
    const FlightPath p({{0, 5.5, 45.1, 1234.5, 90, 1, 2}, {2.5, 5.6, 45.2, 1300, 95, 0, -3}});
    const auto file = write_temp("ts_fly_path_roundtrip.csv", flight_path_csv(p));
    const FlightPath q = read_flight_path(file.string());
    ASSERT_EQ(q.poses().size(), 2u);
    EXPECT_NEAR(q.poses()[1].t_s, 2.5, 1e-9);
    EXPECT_NEAR(q.poses()[1].lon_deg, 5.6, 1e-7);
    EXPECT_NEAR(q.poses()[0].height_m, 1234.5, 1e-2);
    std::filesystem::remove(file);
}

TEST(FlightPath, BadFilesAreOneLineInputErrors) {
    const auto a = write_temp("ts_fly_bad_a.csv", "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n0,5,45,1000,0,0\n");
    EXPECT_THROW(read_flight_path(a.string()), InputError);
    const auto b = write_temp("ts_fly_bad_b.csv", "0,5,45,1000,0,0,0\n0,5,45,1000,0,0,0\n");
    EXPECT_THROW(read_flight_path(b.string()), InputError);  // time does not increase
    const auto c = write_temp("ts_fly_bad_c.csv", "0,5,north,1000,0,0,0\n");
    try {
        read_flight_path(c.string());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("line 1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_flight_path("/nonexistent/path.csv"), InputError);
    for (const auto& f : {a, b, c}) std::filesystem::remove(f);
}

}  // namespace
}  // namespace ts::fly
