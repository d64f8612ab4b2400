// `terrashade bench <what>` (the terrashade-bench executable): measurements behind the charts
// in docs/. Each measured area is one subcommand of `bench`; this file holds `bench sh` (SH
// exponentiation error and cost, log-epsilon trade-off, the optimal-linear fit). Another area
// adds itself by declaring `void add_bench_<area>_command(CLI::App& bench);` in
// app/bench/bench_command.hpp and calling it from add_bench_commands below.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/exp_study.hpp"
#include "app/bench/log_epsilon_study.hpp"
#include "app/command.hpp"
#include "app/io_plan.hpp"
#include "app/bench/study/optimal_linear_fit.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/error.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

struct BenchShOptions {
    std::string csv;
    std::string eps_csv;
    std::string fit_table;
    std::vector<std::string> methods;
    int scenes = 16;
    bool sweep = false;
    double log_eps = -6.907755278982137;
    sh::ExpOptions exp;
};

void write_text(StagedOutputs& outputs, const std::string& path, const std::string& text) {
    outputs.stage(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) throw input_error(path, "cannot write");
    });
}

void run_bench_sh(const BenchShOptions& o) {
    IoPlan plan;
    plan.output("--csv", o.csv, {".csv"}).output("--eps-csv", o.eps_csv, {".csv"});
    plan.output("--fit-optimal-linear", o.fit_table, {});
    plan.check();
    StagedOutputs outputs;
    if (!o.fit_table.empty()) {
        const sh::OptimalLinearFitOptions fit;
        const auto rows = sh::fit_optimal_linear(fit);
        write_text(outputs, o.fit_table, sh::format_optimal_linear_table(rows, fit));
        outputs.commit();
        std::printf("optimal-linear table: %zu rows -> %s\n", rows.size(), o.fit_table.c_str());
        return;
    }
    bench::ExpStudyOptions so;
    so.scenes = o.scenes;
    so.log_eps = o.log_eps;
    so.configs = o.sweep ? bench::sweep_exp_configs() : bench::default_exp_configs(o.exp);
    if (!o.methods.empty()) {
        std::vector<bench::ExpConfig> kept;
        for (const auto& c : so.configs)
            for (const auto& m : o.methods)
                if (c.method == sh::parse_exp_method(m)) kept.push_back(c);
        so.configs = kept;
    }
    const auto rows = bench::run_exp_study(so);
    std::printf("%-6s %-17s %-14s %8s %9s %9s %10s %10s %10s %8s %9s %9s %4s\n", "kind", "method", "param", "blockers",
                "magnitude", "dc", "rms_error", "rms_errmax", "vs_truth", "ns/exp", "min", "max", "nan");
    for (const auto& r : rows)
        std::printf("%-6s %-17s %-14s %8d %9.3g %9.3g %10.3g %10.3g %10.3g %8.1f %9.3g %9.3g %4d\n", r.kind.c_str(),
                    r.method.c_str(), r.param.c_str(), r.blockers, r.magnitude, r.dc, r.rms_error, r.rms_error_max,
                    r.truth_rms_error, r.ns_per_exp, r.min_value, r.max_value, r.nonfinite);
    if (!o.csv.empty()) write_text(outputs, o.csv, bench::exp_study_csv(rows));
    if (!o.eps_csv.empty()) {
        const std::vector<double> eps = {0.3, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 1e-4, 1e-5, 1e-6};
        auto rows_eps = bench::run_log_epsilon_study(eps);
        const auto vis = bench::run_visibility_epsilon_study(
            {0.3, 0.1, 0.05, 0.02, 0.01, 1e-3, 1e-5}, {0, 4, 16, 64, 256, 500}, o.scenes / 2 > 0 ? o.scenes / 2 : 1);
        rows_eps.insert(rows_eps.end(), vis.begin(), vis.end());
        write_text(outputs, o.eps_csv, bench::log_epsilon_csv(rows_eps));
    }
    outputs.commit();
    for (const std::string* path : {&o.csv, &o.eps_csv})
        if (!path->empty()) std::printf("wrote %s\n", path->c_str());
}

void add_bench_sh_command(CLI::App& bench) {
    auto o = std::make_shared<BenchShOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "sh", "SH exponentiation: error against the exact exponential and cost (ns) per method and magnitude");
    cmd->add_option("--csv", o->csv, "Write the table as CSV (input of scripts/chart_sh.py)");
    cmd->add_option("--eps-csv", o->eps_csv, "Also run the log-epsilon trade-off study and write it as CSV");
    cmd->add_option("--fit-optimal-linear", o->fit_table,
                    "Refit the optimal-linear table and write it (core/sh/optimal_linear_table.inc), then exit");
    cmd->add_flag("--sweep", o->sweep,
                  "Sweep each method's accuracy knob (Taylor order, squaring thresholds) for the error-vs-cost chart");
    cmd->add_option("--exp-method", o->methods, "Methods to report (" + sh::exp_method_choices() + "); default all");
    cmd->add_option("--scenes", o->scenes, "Random log vectors per blocker count / magnitude")
        ->capture_default_str()
        ->check(within(1, 100000));
    cmd->add_option("--log-eps", o->log_eps, "Visibility floor log(eps) of the random scenes")
        ->capture_default_str()
        ->check(within(-50.0, -1e-3));
    cmd->add_option("--taylor-order", o->exp.taylor_order, "Highest power for taylor and dc_isolation")
        ->capture_default_str()
        ->check(within(1, 64));
    cmd->add_option("--squaring-threshold", o->exp.squaring_threshold,
                    "scaling_squaring: halve until the norm is below this")
        ->capture_default_str()
        ->check(within(1e-3, 100.0));
    cmd->add_option("--hybrid-threshold", o->exp.hybrid_threshold,
                    "hybrid: optimal linear alone up to this non-DC magnitude, scaling and squaring above")
        ->capture_default_str()
        ->check(within(1e-3, 100.0));
    cmd->callback([o] { run_bench_sh(*o); });
}

}  // namespace

void add_bench_commands(CLI::App& bench_app) {
    CLI::App* bench = &bench_app;
    add_bench_sh_command(*bench);
    add_bench_visibility_command(*bench);
    add_bench_insolation_command(*bench);
    add_bench_render_command(*bench);
    add_bench_relight_command(*bench);
    add_bench_transfer_command(*bench);
    add_bench_sun_command(*bench);
    add_bench_spheres_command(*bench);
    add_bench_blockers_command(*bench);
    add_bench_tiles_command(*bench);
    add_bench_dem_command(*bench);
    add_bench_bounce_command(*bench);
#ifdef TERRASHADE_HAS_GPU
    add_bench_fly_command(*bench);
#endif
    add_bench_report_command(*bench);
    // Further areas: add_bench_<area>_command(*bench); declared in app/bench/bench_command.hpp.
}

}  // namespace ts::app
