#include "app/bench/report_table.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "app/bench/csv_number.hpp"

namespace ts::bench {

namespace {
// A text field as RFC 4180 writes it: quoted (quotes doubled) when it holds a comma or a quote.
std::string csv_text(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}
}  // namespace

std::string report_csv(const std::vector<ReportRow>& rows) {
    std::ostringstream out;
    out << "command,knob,value,is_default,seconds,error,error_metric,dem\n";
    for (const ReportRow& r : rows)
        out << csv_text(r.command) << ',' << csv_text(r.knob) << ',' << csv_text(r.value) << ','
            << (r.is_default ? 1 : 0) << ',' << app::csv_number(r.seconds) << ',' << app::csv_number(r.error) << ','
            << csv_text(r.error_metric) << ',' << csv_text(r.dem) << '\n';
    return out.str();
}

namespace {
std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> f;
    std::string cur;
    for (char c : line) {
        if (c == ',') {
            f.push_back(cur);
            cur.clear();
        } else if (c != '\r') {
            cur += c;
        }
    }
    f.push_back(cur);
    return f;
}
}  // namespace

std::vector<CsvRecord> read_csv_records(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::vector<CsvRecord> rows;
    if (!std::getline(in, line)) return rows;
    const std::vector<std::string> header = split(line);
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const std::vector<std::string> f = split(line);
        CsvRecord r;
        for (std::size_t i = 0; i < header.size() && i < f.size(); ++i) r[header[i]] = f[i];
        rows.push_back(std::move(r));
    }
    return rows;
}

double csv_field(const CsvRecord& r, const std::string& name) {
    const auto it = r.find(name);
    if (it == r.end() || it->second.empty()) return std::numeric_limits<double>::quiet_NaN();
    char* end = nullptr;
    const double v = std::strtod(it->second.c_str(), &end);
    return end == it->second.c_str() ? std::numeric_limits<double>::quiet_NaN() : v;
}

}  // namespace ts::bench
