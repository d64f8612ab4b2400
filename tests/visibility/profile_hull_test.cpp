// The exact sweep's building blocks against brute force: DelayedHull (the far-field tangent of
// a profile), its two interfaces against each other, and RowMetrics' hinted row search.
#include "core/util/angles.hpp"
#include "core/visibility/profile_hull.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/row_metrics.hpp"

using namespace ts::visibility;
using ts::radians;

namespace {

struct Profile {
    std::vector<double> s, u;
};

// A rough profile with irregular spacing (as a sweep line's samples and blockers are), with
// some exactly collinear runs (ties in the hull's tests).
Profile random_profile(unsigned seed, int n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> step(0.05, 1.0), height(-50.0, 50.0);
    Profile p;
    double s = 0;
    for (int i = 0; i < n; ++i) {
        s += (i % 17 < 4) ? 0.25 : step(rng);
        p.s.push_back(s);
        p.u.push_back((i % 17 < 4) ? 10.0 - 2.0 * s : height(rng));
    }
    return p;
}

// Largest slope from point i to the earlier points at least `delay` behind it.
double brute_force(const Profile& p, int i, double delay) {
    double best = ProfileHull::kNone;
    for (int j = 0; j < i; ++j)
        if (p.s[j] <= p.s[i] - delay) best = std::max(best, (p.u[j] - p.u[i]) / (p.s[i] - p.s[j]));
    return best;
}

}  // namespace

TEST(DelayedHullTest, MatchesBruteForceWithAndWithoutDelay) {
    for (double delay : {0.0, 0.7, 3.0}) {
        for (unsigned seed = 1; seed <= 4; ++seed) {
            const Profile p = random_profile(seed, 400);
            DelayedHull owner(delay);
            DelayedHull::Line line = owner.begin_line(p.s.size());
            for (int i = 0; i < int(p.s.size()); ++i) {
                const double got = line.query(p.s[i], p.u[i]);
                line.add(p.s[i], p.u[i]);
                const double want = brute_force(p, i, delay);
                if (want == ProfileHull::kNone)
                    EXPECT_EQ(got, ProfileHull::kNone) << "delay " << delay << " point " << i;
                else  // the hull's tangent is the brute force's maximiser, up to rounding
                    EXPECT_NEAR(got, want, 1e-9 * (1 + std::abs(want))) << "delay " << delay << " point " << i;
            }
        }
    }
}

// The hinted search gives the same bits as the unhinted one from any hint (geographic rows:
// dx varies by row).
TEST(RowMetricsTest, HintedRowOfGMatchesUnhinted) {
    const std::vector<float> z(4 * 200, 0.0f);
    ts::terrain::HeightGrid grid;
    grid.width = 4;
    grid.height = 200;
    grid.z = z;
    for (int r = 0; r < grid.height; ++r) {
        grid.dy_m.push_back(92.6);
        grid.dx_m.push_back(92.6 * std::cos(radians(60.0 - 0.3 * r)));
    }
    const RowMetrics m(grid);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> value(-1.0, m.g_max() + 1.0);
    std::vector<double> values;
    for (int i = 0; i < 2000; ++i) values.push_back(value(rng));
    for (int r = 0; r < grid.height; ++r) values.push_back(m.g(r));  // knots: two brackets fit
    for (double v : values)
        for (int hint : {-5, 0, 17, 100, 198, 199, 500}) {
            int h = hint;
            const double a = m.row_of_g(v), b = m.row_of_g(v, h);
            EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "value " << v << " hint " << hint;
        }
}
