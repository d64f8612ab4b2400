#pragma once
// The wall time a shard may take (`plan --wall-time`), and how many shards fit a job into it.
#include <cstdint>
#include <string>

namespace ts::app {

// "90s", "45m", "2h", "1h30m", "1d", or Slurm's "[D-]HH:MM:SS" / "MM:SS" -> seconds (> 0);
// ts::InputError otherwise.
double parse_wall_time(const std::string& text);
// "2 h 05 min", "12.3 s": for reports.
std::string format_duration(double seconds);
std::string format_bytes(double bytes);
// Slurm's --time format, rounded up to the minute: "45:00", "2:00:00", "1-12:00:00".
std::string slurm_time(double seconds);

// The fewest shards N such that fixed_s + work_s / N <= wall_s (each shard pays fixed_s, shares
// work_s); 0 if even one item per shard cannot fit (fixed_s >= wall_s).
std::int64_t shards_for_wall_time(double work_s, double fixed_s, double wall_s);

}  // namespace ts::app
