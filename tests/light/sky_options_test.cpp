// parse_sky_options: the --sky grammar and its one-line errors.
#include <gtest/gtest.h>

#include "core/light/sky.hpp"
#include "core/util/error.hpp"

namespace ts::light {
namespace {

TEST(SkyOptions, ClearAndOvercast) {
    // The clear sky is the physical one; Preetham's is asked for by name.
    SkyOptions o = parse_sky_options("clear");
    EXPECT_EQ(o.kind, SkyOptions::Kind::physical);
    EXPECT_EQ(SkyOptions().kind, SkyOptions::Kind::physical);
    EXPECT_EQ(o.turbidity, 3.0);
    o = parse_sky_options("clear:turbidity=5.5,albedo=0.1");
    EXPECT_EQ(o.turbidity, 5.5);
    EXPECT_EQ(o.ground_albedo, 0.1);
    o = parse_sky_options("CLEAR:Albedo=0");
    EXPECT_EQ(o.ground_albedo, 0.0);
    o = parse_sky_options("physical:turbidity=4");
    EXPECT_EQ(o.kind, SkyOptions::Kind::physical);
    EXPECT_EQ(o.turbidity, 4.0);
    EXPECT_TRUE(o.multiple_scattering);
    EXPECT_NE(make_sky(o, {0, 0.5, 0.5})->describe().find("multiple scattering"), std::string::npos);
    o = parse_sky_options("physical:scattering=Single,albedo=0.3");
    EXPECT_FALSE(o.multiple_scattering);
    EXPECT_EQ(o.ground_albedo, 0.3);
    EXPECT_NE(make_sky(o, {0, 0.5, 0.5})->describe().find("single scattering"), std::string::npos);
    EXPECT_THROW(parse_sky_options("physical:scattering=double"), InputError);
    EXPECT_EQ(parse_sky_options("physical").aureole_deg, 30.0);
    EXPECT_EQ(parse_sky_options("physical:aureole=0").aureole_deg, 0.0);
    EXPECT_THROW(parse_sky_options("physical:aureole=-5"), InputError);
    EXPECT_THROW(parse_sky_options("overcast:aureole=10"), InputError);
    EXPECT_EQ(parse_sky_options("Preetham:turbidity=4").kind, SkyOptions::Kind::preetham);
    EXPECT_NE(make_sky(parse_sky_options("preetham"), {0, 0.5, 0.5})->describe().find("Preetham"), std::string::npos);
    EXPECT_THROW(parse_sky_options("preetham:scattering=single"), InputError);
    EXPECT_THROW(parse_sky_options("preetham:aureole=10"), InputError);
    o = parse_sky_options("overcast:brightness=2");
    EXPECT_EQ(o.kind, SkyOptions::Kind::overcast);
    EXPECT_EQ(o.overcast_brightness, 2.0);
}

TEST(SkyOptions, HdrPaths) {
    SkyOptions o = parse_sky_options("maps/sky.exr");
    EXPECT_EQ(o.kind, SkyOptions::Kind::hdr);
    EXPECT_EQ(o.hdr_path, "maps/sky.exr");
    o = parse_sky_options("Sky.HDR,rotation=90,scale=0.5");
    EXPECT_EQ(o.hdr_path, "Sky.HDR");
    EXPECT_EQ(o.hdr_rotation_deg, 90.0);
    EXPECT_EQ(o.hdr_scale, 0.5);
    o = parse_sky_options("hdr:/data/a,b/pano.pfm,scale=2");  // any extension and commas with hdr:
    EXPECT_EQ(o.hdr_path, "/data/a,b/pano.pfm");
    EXPECT_EQ(o.hdr_scale, 2.0);
    o = parse_sky_options("hdr:C:/x.exr");  // the first colon only
    EXPECT_EQ(o.hdr_path, "C:/x.exr");
}

void expect_error(const char* text, const char* needle) {
    try {
        parse_sky_options(text);
        ADD_FAILURE() << "no error for '" << text << "'";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(needle), std::string::npos) << text << " -> " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind("sky: ", 0), 0u) << what;
    }
}

TEST(SkyOptions, ErrorsAreOneLine) {
    expect_error("", "empty");
    expect_error("cloudy", "unknown sky 'cloudy'");
    expect_error("clear:turbidity=12", "turbidity must be in 1.7..10, got 12");
    expect_error("clear:turbidity=abc", "turbidity must be a number");
    expect_error("clear:turbidity=nan", "turbidity must be a number");
    expect_error("clear:albedo=1.5", "albedo must be in 0..1");
    expect_error("clear:brightness=2", "unknown parameter 'brightness' for clear");
    expect_error("overcast:turbidity=3", "unknown parameter 'turbidity' for overcast");
    expect_error("overcast:brightness=0", "brightness must be in (0, 1000]");
    expect_error("clear:", "nothing after");
    expect_error("clear:turbidity", "want key=value");
    expect_error("sky.exr,scale=-1", "scale must be > 0");
    expect_error("sky.exr,tilt=3", "unknown HDR parameter 'tilt'");
    expect_error("hdr:", "no HDR map path");
}

}  // namespace
}  // namespace ts::light
