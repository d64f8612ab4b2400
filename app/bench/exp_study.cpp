#include "app/bench/exp_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/bench/error_stats.hpp"
#include "core/sh/exact_exp.hpp"
#include "core/sh/log_scenes.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::bench {

using namespace ts::sh;

namespace {

struct Case {
    std::string kind;
    int blockers;
    std::vector<ShVec> logs;
    std::vector<ShVec> exact;
    std::vector<ShVec> truth;   // scenes only
    std::vector<ShVec> binary;  // scenes only
};

double time_method(ExpMethod method, const std::vector<ShVec>& logs, const ExpOptions& opt, double min_seconds) {
    std::vector<float> in(logs.size() * kCount), out(logs.size() * kCount);
    for (std::size_t v = 0; v < logs.size(); ++v)
        for (int i = 0; i < kCount; ++i) in[v * kCount + i] = static_cast<float>(logs[v][i]);
    long long calls = 0;
    volatile float sink = 0.0f;  // keeps the work observable
    const Stopwatch watch;
    double elapsed = 0.0;
    do {
        for (std::size_t v = 0; v < logs.size(); ++v) sh_exp(method, &in[v * kCount], &out[v * kCount], opt);
        sink = sink + out[0];
        calls += static_cast<long long>(logs.size());
        elapsed = watch.seconds();
    } while (elapsed < min_seconds);
    return elapsed * 1e9 / static_cast<double>(calls);
}

ExpStudyRow evaluate(const Case& c, const ExpConfig& config, const ExactExp& exact, double min_seconds) {
    const ExpMethod method = config.method;
    const ExpOptions& opt = config.options;
    ExpStudyRow row;
    row.kind = c.kind;
    row.method = std::string(to_string(method));
    row.param = config.param;
    row.blockers = c.blockers;
    row.min_value = std::numeric_limits<double>::infinity();
    row.max_value = -std::numeric_limits<double>::infinity();
    row.exact_min = row.min_value;
    row.exact_max = row.max_value;
    // Per vector of the case (at least one: scenes >= 1); the row reports their means and the
    // largest RMS error. A vector with a non-finite coefficient is counted in `nonfinite` and
    // weighs 0 in the means.
    std::vector<double> magnitude, dc, rms, rel, truth_rms, exact_truth_rms, binary_rms;
    const auto weigh_zero = [&] {
        for (auto* v : {&magnitude, &dc, &rms, &rel, &truth_rms, &exact_truth_rms, &binary_rms}) v->push_back(0.0);
    };
    for (std::size_t v = 0; v < c.logs.size(); ++v) {
        float in[kCount], out[kCount];
        for (int i = 0; i < kCount; ++i) in[i] = static_cast<float>(c.logs[v][i]);
        sh_exp(method, in, out, opt);
        ShVec approx{};
        bool finite = true;
        for (int i = 0; i < kCount; ++i) {
            approx[i] = out[i];
            finite = finite && std::isfinite(out[i]);
        }
        if (!finite) {
            ++row.nonfinite;
            weigh_zero();
            continue;
        }
        // |a - b| / sqrt(4 pi) is the RMS over the sphere of the difference (orthonormal basis).
        const double err = norm(approx - c.exact[v]);
        magnitude.push_back(non_dc_norm(c.logs[v]));
        dc.push_back(c.logs[v][0]);
        rms.push_back(err / kSqrt4Pi);
        rel.push_back(err / std::max(norm(c.exact[v]), 1e-300));
        const ExactExp::Range r = exact.range(approx);
        row.min_value = std::min(row.min_value, r.min);
        row.max_value = std::max(row.max_value, r.max);
        const ExactExp::Range e = exact.range(c.exact[v]);
        row.exact_min = std::min(row.exact_min, e.min);
        row.exact_max = std::max(row.exact_max, e.max);
        if (!c.truth.empty()) {
            truth_rms.push_back(norm(approx - c.truth[v]) / kSqrt4Pi);
            exact_truth_rms.push_back(norm(c.exact[v] - c.truth[v]) / kSqrt4Pi);
            binary_rms.push_back(norm(approx - c.binary[v]) / kSqrt4Pi);
        }
    }
    row.magnitude = mean(magnitude);
    row.dc = mean(dc);
    row.rms_error = mean(rms);
    row.rms_error_max = max_value(rms);
    row.rel_error = mean(rel);
    if (!c.truth.empty()) {
        row.truth_rms_error = mean(truth_rms);
        row.exact_truth_rms_error = mean(exact_truth_rms);
        row.binary_rms_error = mean(binary_rms);
    }
    row.ns_per_exp = time_method(method, c.logs, opt, min_seconds);
    return row;
}

}  // namespace

std::vector<ExpConfig> default_exp_configs(const ExpOptions& options) {
    std::vector<ExpConfig> c;
    for (ExpMethod m : kAllExpMethods) c.push_back({m, options, "default"});
    return c;
}

std::vector<ExpConfig> sweep_exp_configs() {
    std::vector<ExpConfig> c;
    for (ExpMethod m : {ExpMethod::taylor, ExpMethod::dc_isolation})
        for (int order : {2, 3, 4, 6, 8, 12}) {
            ExpOptions o;
            o.taylor_order = order;
            c.push_back({m, o, "order=" + std::to_string(order)});
        }
    c.push_back({ExpMethod::optimal_linear, ExpOptions{}, "table"});
    for (float t : {0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f}) {
        char label[32];
        std::snprintf(label, sizeof label, "threshold=%g", t);
        ExpOptions s;
        s.squaring_threshold = t;
        c.push_back({ExpMethod::scaling_squaring, s, label});
        ExpOptions h;
        h.hybrid_threshold = t;
        c.push_back({ExpMethod::hybrid, h, label});
    }
    return c;
}

std::vector<ExpStudyRow> run_exp_study(const ExpStudyOptions& o) {
    const ExactExp exact;
    const SphereQuadrature truth_quad(180, 360);
    SplitMix64 rng(o.seed);
    std::vector<Case> cases;
    for (int b : o.blocker_counts) {
        Case c{"scene", b, {}, {}};
        SceneOptions so;
        so.blockers = b;
        so.height_field = o.height_field;
        so.log_eps = o.log_eps;
        for (int s = 0; s < o.scenes; ++s) {
            const LogScene scene = random_scene(so, rng);
            c.logs.push_back(scene.log_sh());
            // The true visibility has sharp cap edges: a finer grid (1 deg) than the reference.
            c.truth.push_back(truth_quad.project([&](const glm::dvec3& d) { return std::exp(scene.true_log(d)); }));
            c.binary.push_back(
                truth_quad.project([&](const glm::dvec3& d) { return scene.true_log(d) < 0.0 ? 0.0 : 1.0; }));
        }
        cases.push_back(std::move(c));
    }
    for (double m : o.magnitudes) {
        Case c{"shape", 0, {}, {}};
        for (int s = 0; s < o.scenes; ++s) c.logs.push_back(m * random_log_shape(rng));
        cases.push_back(std::move(c));
    }
    for (Case& c : cases)
        for (const ShVec& f : c.logs) c.exact.push_back(exact(f));

    std::vector<ExpStudyRow> rows;
    for (const Case& c : cases)
        for (const ExpConfig& config : o.configs) rows.push_back(evaluate(c, config, exact, o.min_timing_seconds));
    return rows;
}

std::string exp_study_csv(const std::vector<ExpStudyRow>& rows) {
    std::string s =
        "kind,method,param,blockers,magnitude,dc,rms_error,rms_error_max,rel_error,ns_per_exp,min_value,max_value,"
        "exact_min,exact_max,nonfinite,truth_rms_error,exact_truth_rms_error,binary_rms_error\n";
    char line[512];
    for (const ExpStudyRow& r : rows) {
        std::snprintf(line, sizeof line,
                      "%s,%s,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g\n",
                      r.kind.c_str(), r.method.c_str(), r.param.c_str(), r.blockers, r.magnitude, r.dc, r.rms_error,
                      r.rms_error_max, r.rel_error, r.ns_per_exp, r.min_value, r.max_value, r.exact_min, r.exact_max,
                      r.nonfinite, r.truth_rms_error, r.exact_truth_rms_error, r.binary_rms_error);
        s += line;
    }
    return s;
}

}  // namespace ts::bench
