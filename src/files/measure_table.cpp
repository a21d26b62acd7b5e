#include "files/measure_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace noneuclid::files {

namespace {

// One row: a number and its unit, or a word (`word` not null: "yes", "no").
struct Row {
    const char* name;
    double value;
    TableUnit unit;
    const char* word = nullptr;
};

// Characters on a terminal: UTF-8 bytes that do not continue a character ("×" is one).
std::size_t columns(const std::string& s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// The heading and the rows, names left-aligned and values right-aligned in their columns.
void append_table(std::string& out, const char* instrument, double K, const std::vector<Row>& rows) {
    char k[32];
    std::snprintf(k, sizeof k, "%g", K == 0 ? 0.0 : K);
    out += std::string(instrument) + " at K = " + k + "\n";
    std::vector<std::string> values;
    std::size_t name_width = 0, value_width = 0;
    for (const Row& r : rows) {
        values.push_back(r.word ? std::string(r.word) : table_number(r.value, table_decimals(r.unit)));
        name_width = std::max(name_width, columns(r.name));
        value_width = std::max(value_width, values.back().size());
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
        std::string line = rows[i].name;
        line.append(name_width - columns(line) + 2 + value_width - values[i].size(), ' ');
        line += values[i];
        const char* unit = rows[i].word ? "" : table_unit_name(rows[i].unit);
        if (*unit) line += std::string("  ") + unit;
        out += line + "\n";
    }
}

}  // namespace

int table_decimals(TableUnit u) {
    switch (u) {
        case TableUnit::angle: return 1;
        case TableUnit::count: return 0;
        default: return 3;
    }
}

const char* table_unit_name(TableUnit u) {
    switch (u) {
        case TableUnit::angle: return "°";
        case TableUnit::length: return "units";
        case TableUnit::area: return "units²";
        case TableUnit::curvature: return "1/units²";
        default: return "";
    }
}

std::string table_number(double v, int decimals) {
    if (!std::isfinite(v)) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    // "-0.000": a small negative value rounded to zero; zero has no sign.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

void append_triangle_table(std::string& out, double K, const geo::TriangleReading& t) {
    using U = TableUnit;
    append_table(out, "triangle", K,
                 {{"side a", t.side[0], U::length},
                  {"side b", t.side[1], U::length},
                  {"side c", t.side[2], U::length},
                  {"angle A", t.angle_deg[0], U::angle},
                  {"angle B", t.angle_deg[1], U::angle},
                  {"angle C", t.angle_deg[2], U::angle},
                  {"angle sum", t.sum_deg, U::angle},
                  {"excess", t.excess_deg, U::angle},
                  {"area", t.area, U::area},
                  {"K × area", t.k_area_deg, U::angle}});
}

void append_circle_table(std::string& out, double K, const geo::CircleReading& c) {
    using U = TableUnit;
    append_table(out, "circle", K,
                 {{"radius", c.radius, U::length},
                  {"circumference", c.circumference, U::length},
                  {"flat circumference", c.flat_circumference, U::length},
                  {"circumference ratio", c.circumference_ratio, U::ratio},
                  {"area", c.area, U::area},
                  {"flat area", c.flat_area, U::area},
                  {"area ratio", c.area_ratio, U::ratio}});
}

void append_parallels_table(std::string& out, double K, const geo::ParallelsReading& p) {
    using U = TableUnit;
    std::vector<Row> rows = {{"distance", p.start, U::length},
                             {"length", p.length, U::length},
                             {"apart", p.distance, U::length},
                             {"ratio", p.ratio, U::ratio},
                             {"meet", 0, U::ratio, p.meet ? "yes" : "no"}};
    if (p.meet) rows.push_back({"meet at", p.meet_at, U::length});
    append_table(out, "parallels", K, rows);
}

void append_polygon_table(std::string& out, double K, const geo::PolygonReading& r) {
    using U = TableUnit;
    append_table(out, "polygon", K,
                 {{"sides", static_cast<double>(r.sides), U::count},
                  {"around", static_cast<double>(r.around), U::count},
                  {"side", r.side, U::length},
                  {"angle", r.angle_deg, U::angle},
                  {"gap", r.gap_deg, U::angle},
                  {"closing K", r.closing_K, U::curvature}});
}

}  // namespace noneuclid::files
