#include "core/raster/gdal_band_metadata.hpp"

#include <cstddef>

namespace ts::raster {
namespace {

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// GDAL numbers the samples of the XML from 0 (band 1 is sample="0"); the item names are those
// GDAL itself writes for these roles. The value is escaped twice, as GDAL writes it (it
// escapes the value, then serialises the XML) and reads it (it parses the XML, then unescapes
// the value): escaped once, "a & b" would read back as "a ".
std::string item(const char* name, std::size_t sample, const char* role, const std::string& value) {
    return "  <Item name=\"" + std::string(name) + "\" sample=\"" + std::to_string(sample) + "\" role=\"" + role +
           "\">" + xml_escape(xml_escape(value)) + "</Item>\n";
}

}  // namespace

std::string gdal_band_metadata_xml(int bands, const std::vector<std::string>& descriptions,
                                   const std::vector<std::string>& units) {
    std::string items;
    for (std::size_t b = 0; b < std::size_t(bands > 0 ? bands : 0); ++b) {
        if (b < descriptions.size() && !descriptions[b].empty())
            items += item("DESCRIPTION", b, "description", descriptions[b]);
        if (b < units.size() && !units[b].empty()) items += item("UNITTYPE", b, "unittype", units[b]);
    }
    return items.empty() ? std::string() : "<GDALMetadata>\n" + items + "</GDALMetadata>";
}

}  // namespace ts::raster
