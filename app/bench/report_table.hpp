#pragma once
// `bench report`'s one table: a row per (command, knob, value) measured, with its time and its
// error against that command's reference, and a reader for the CSVs the other bench commands
// write (so the report reuses their measurements instead of repeating them).
#include <map>
#include <string>
#include <vector>

namespace ts::bench {

struct ReportRow {
    std::string command;  // the terrashade command the knob belongs to (visibility, render, ...)
    std::string knob;     // the option (as named in docs/user-guide.md)
    std::string value;
    bool is_default = false;
    double seconds = 0;   // NaN where the knob does not change the time (an error-only study)
    double error = 0;
    std::string error_metric;
    std::string dem;
};

std::string report_csv(const std::vector<ReportRow>& rows);

// A CSV file as a list of rows keyed by its header's names (no quoting: the bench CSVs have none).
using CsvRecord = std::map<std::string, std::string>;
std::vector<CsvRecord> read_csv_records(const std::string& text);
// The field as a number; NaN if missing or empty.
double csv_field(const CsvRecord& r, const std::string& name);

}  // namespace ts::bench
