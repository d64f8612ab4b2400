#include "app/bench/log_epsilon_study.hpp"

#include <cmath>
#include <cstdio>

#include "app/bench/exp_study.hpp"
#include "core/blockers/sphere_blocker.hpp"
#include "core/material/log_brdf.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/sh/sphere_quadrature.hpp"
#include "core/util/angles.hpp"

namespace ts::bench {

using namespace ts::sh;

namespace {

LogEpsilonRow evaluate(const std::string& name, double eps, const ShVec& f_log, const ShVec& truth, double albedo_true,
                       const SphereQuadrature& q) {
    float in[kCount], out[kCount];
    for (int i = 0; i < kCount; ++i) in[i] = static_cast<float>(f_log[i]);
    sh_exp(ExpMethod::hybrid, in, out);
    ShVec g{};
    for (int i = 0; i < kCount; ++i) g[i] = out[i];
    LogEpsilonRow r;
    r.lobe = name;
    r.eps = eps;
    r.magnitude = non_dc_norm(f_log);
    r.rms_error = norm(g - truth) / kSqrt4Pi;
    r.albedo = g[0] * kSqrt4Pi;
    r.albedo_true = albedo_true;
    r.lower_leak = q.integrate([&](const glm::dvec3& d) { return d.z < 0.0 ? std::abs(reconstruct(g, d)) : 0.0; });
    return r;
}

}  // namespace

std::vector<LogEpsilonRow> run_log_epsilon_study(const std::vector<double>& eps_values) {
    const SphereQuadrature q(400, 64);
    std::vector<LogEpsilonRow> rows;
    for (double alpha : {1.0, 10.0, 100.0}) {
        const std::string name = alpha == 1.0 ? "diffuse" : "phong" + std::to_string(static_cast<int>(alpha));
        const ShVec truth = q.project(
            [&](const glm::dvec3& d) { return d.z > 0.0 ? (alpha + 1.0) / (2.0 * kPi) * std::pow(d.z, alpha) : 0.0; });
        for (double eps : eps_values) {
            const ShVec f = zh_rotate(log_phong_zh(alpha, std::log(eps)), {0, 0, 1});
            rows.push_back(evaluate(name, eps, f, truth, 1.0, q));
        }
    }
    // Visibility: a sphere blocker of 20 deg angular radius overhead.
    const double tb = radians(20.0);  // equal to 20 pi / 180 to the last bit
    const ShVec vis = q.project([&](const glm::dvec3& d) { return d.z > std::cos(tb) ? 0.0 : 1.0; });
    for (double eps : eps_values) {
        const ShVec f = zh_rotate(blockers::sphere_log_zh(tb, std::log(eps)), {0, 0, 1});
        rows.push_back(evaluate("sphere", eps, f, vis, 4.0 * kPi - blockers::cap_solid_angle(tb), q));
    }
    return rows;
}

std::vector<LogEpsilonRow> run_visibility_epsilon_study(const std::vector<double>& eps_values,
                                                        const std::vector<int>& blocker_counts, int scenes) {
    std::vector<LogEpsilonRow> rows;
    for (double eps : eps_values) {
        ExpStudyOptions o;
        o.blocker_counts = blocker_counts;
        o.magnitudes.clear();
        o.scenes = scenes;
        o.log_eps = std::log(eps);
        o.configs = {{ExpMethod::hybrid, ExpOptions{}, "default"}};
        o.min_timing_seconds = 0.0;
        for (const ExpStudyRow& r : run_exp_study(o)) {
            LogEpsilonRow row;
            row.lobe = "vis_" + std::to_string(r.blockers);
            row.eps = eps;
            row.magnitude = r.magnitude;
            row.rms_error = r.binary_rms_error;
            rows.push_back(row);
        }
    }
    return rows;
}

std::string log_epsilon_csv(const std::vector<LogEpsilonRow>& rows) {
    std::string s = "lobe,eps,magnitude,rms_error,albedo,albedo_true,lower_leak\n";
    char line[256];
    for (const LogEpsilonRow& r : rows) {
        std::snprintf(line, sizeof line, "%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.lobe.c_str(), r.eps, r.magnitude,
                      r.rms_error, r.albedo, r.albedo_true, r.lower_leak);
        s += line;
    }
    return s;
}

}  // namespace ts::bench
