// `noneuclid measure --format table` (files/measure_table.hpp) against the JSON of the same
// readings (files/measure_json.hpp, 17 digits) as the reference: both are printed and parsed
// back here, and each row of the table must be the JSON's number rounded to the row's places
// (within half a unit in its last place, plus 1e-9 for the parse), printed with exactly that
// many decimals, never as "-0", with the unit the row's kind has. Every reading the JSON has
// must have its row, for each instrument at curvatures from -1 to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "files/measure_json.hpp"
#include "files/measure_table.hpp"

namespace noneuclid {
namespace {

// Field `key` of a flat JSON object, its element `index` if it is a list (-1: a number).
double json_number(const std::string& json, const std::string& key, int index) {
    const std::size_t at = json.find("\"" + key + "\":");
    EXPECT_NE(at, std::string::npos) << key << " in " << json;
    if (at == std::string::npos) return NAN;
    const char* p = json.c_str() + at + key.size() + 3;
    if (index >= 0) {
        EXPECT_EQ(*p, '[') << key;
        ++p;
        for (int i = 0; i < index; ++i) p = std::strchr(p, ',') + 1;
    }
    return std::strtod(p, nullptr);
}

struct TableRow {
    std::string name, value, unit;
};
// The table's rows (after its heading), split at runs of two spaces or more: name, value, unit.
std::vector<TableRow> parse_table(const std::string& table, std::string& heading) {
    std::vector<TableRow> rows;
    std::size_t at = table.find('\n');
    heading = table.substr(0, at);
    while (at != std::string::npos && at + 1 < table.size()) {
        const std::size_t end = table.find('\n', at + 1);
        const std::string line = table.substr(at + 1, end - at - 1);
        std::vector<std::string> cells;
        std::size_t i = 0;
        while (i < line.size()) {
            std::size_t gap = line.find("  ", i);
            if (gap == std::string::npos) gap = line.size();
            cells.push_back(line.substr(i, gap - i));
            i = line.find_first_not_of(' ', gap);
            if (i == std::string::npos) break;
        }
        cells.resize(3);
        rows.push_back({cells[0], cells[1], cells[2]});
        at = end;
    }
    return rows;
}

// What a row should be: its JSON field (and element), its unit's text and its decimals.
struct Expected {
    const char* name;
    const char* key;
    int index;
    const char* unit;
    int decimals;
};
constexpr const char* kDeg = "°";

void expect_rows(const std::string& table, const std::string& json, const std::vector<Expected>& expected,
                 const std::string& heading) {
    SCOPED_TRACE(table + json);
    std::string got_heading;
    const std::vector<TableRow> rows = parse_table(table, got_heading);
    EXPECT_EQ(got_heading, heading);
    ASSERT_EQ(rows.size(), expected.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Expected& e = expected[i];
        const TableRow& r = rows[i];
        EXPECT_EQ(r.name, e.name);
        EXPECT_EQ(r.unit, e.unit) << e.name;
        if (e.decimals < 0) {  // a word for the JSON's boolean
            EXPECT_EQ(r.value, json.find("\"" + std::string(e.key) + "\":true") != std::string::npos ? "yes" : "no");
            continue;
        }
        const std::size_t point = r.value.find('.');
        EXPECT_EQ(point == std::string::npos ? 0 : int(r.value.size() - point - 1), e.decimals)
            << e.name << " " << r.value;
        EXPECT_EQ(r.value.find_first_not_of("-0123456789."), std::string::npos) << e.name << " " << r.value;
        const double v = std::strtod(r.value.c_str(), nullptr);
        if (v == 0) {
            EXPECT_NE(r.value[0], '-') << e.name << " " << r.value;
        }
        const double reference = json_number(json, e.key, e.index);
        EXPECT_LE(std::fabs(v - reference), 0.5 * std::pow(10.0, -e.decimals) + 1e-9)
            << e.name << " " << r.value << " vs " << reference;
    }
}

std::string heading(const char* instrument, double K) {
    char k[32];
    std::snprintf(k, sizeof k, "%g", K);
    return std::string(instrument) + " at K = " + k;
}

constexpr double kCurvatures[] = {-1, -0.5, -0.1234, -1e-9, 0, 1e-9, 0.01, 0.3, 0.75, 1};

TEST(MeasureTable, TriangleRowsAreTheJsonRounded) {
    const std::vector<Expected> rows = {
        {"side a", "sides", 0, "units", 3}, {"side b", "sides", 1, "units", 3}, {"side c", "sides", 2, "units", 3},
        {"angle A", "angles", 0, kDeg, 1},  {"angle B", "angles", 1, kDeg, 1},  {"angle C", "angles", 2, kDeg, 1},
        {"angle sum", "angle_sum", -1, kDeg, 1}, {"excess", "excess", -1, kDeg, 1}, {"area", "area", -1, "units²", 3},
        {"K × area", "K_area", -1, kDeg, 1}};
    const geo::Polar<double> shapes[][3] = {{{1, 1.5707963267948966}, {1, 3.6651914291880923}, {1, 5.7595865315812871}},
                                            {{0.2, 0.1}, {1.7, 2.0}, {0.9, -2.5}},
                                            {{0.01, 0}, {0.02, 1.0}, {0.015, 2.0}}};
    for (const auto& v : shapes)
        for (double K : kCurvatures) {
            geo::TriangleReading t;
            ASSERT_EQ(geo::measure_triangle(K, v, 3.14, t), geo::MeasureError::none);
            std::string table, json;
            files::append_triangle_table(table, K, t);
            files::append_triangle_json(json, K, v, geo::MeasureError::none, t);
            expect_rows(table, json, rows, heading("triangle", K));
        }
}

TEST(MeasureTable, CircleRowsAreTheJsonRounded) {
    const std::vector<Expected> rows = {{"radius", "radius", -1, "units", 3},
                                        {"circumference", "circumference", -1, "units", 3},
                                        {"flat circumference", "flat_circumference", -1, "units", 3},
                                        {"circumference ratio", "circumference_ratio", -1, "", 3},
                                        {"area", "area", -1, "units²", 3},
                                        {"flat area", "flat_area", -1, "units²", 3},
                                        {"area ratio", "area_ratio", -1, "", 3}};
    for (double rho : {0.001, 0.5, 2.5})
        for (double K : kCurvatures) {
            geo::CircleReading c;
            ASSERT_EQ(geo::measure_circle(K, {0.5, 0.3}, rho, 3.14, c), geo::MeasureError::none);
            std::string table, json;
            files::append_circle_table(table, K, c);
            files::append_circle_json(json, K, {0.5, 0.3}, rho, geo::MeasureError::none, c);
            expect_rows(table, json, rows, heading("circle", K));
        }
}

TEST(MeasureTable, ParallelsRowsAreTheJsonRounded) {
    for (double K : kCurvatures) {
        geo::ParallelsReading p;
        ASSERT_EQ(geo::measure_parallels(K, 0.5, 2, p), geo::MeasureError::none);
        std::string table, json;
        files::append_parallels_table(table, K, p);
        files::append_parallels_json(json, K, 0.5, 2, geo::MeasureError::none, p);
        std::vector<Expected> rows = {{"distance", "distance", -1, "units", 3},
                                      {"length", "length", -1, "units", 3},
                                      {"apart", "apart", -1, "units", 3},
                                      {"ratio", "ratio", -1, "", 3},
                                      {"meet", "meet", -1, "", -1}};
        if (K > 0) rows.push_back({"meet at", "meet_at", -1, "units", 3});
        expect_rows(table, json, rows, heading("parallels", K));
    }
}

TEST(MeasureTable, PolygonRowsAreTheJsonRounded) {
    const std::vector<Expected> rows = {{"sides", "sides", -1, "", 0},
                                        {"around", "around", -1, "", 0},
                                        {"side", "side", -1, "units", 3},
                                        {"angle", "angle", -1, kDeg, 1},
                                        {"gap", "gap", -1, kDeg, 1},
                                        {"closing K", "closing_K", -1, "1/units²", 3}};
    const int pq[][2] = {{3, 7}, {4, 4}, {6, 3}, {5, 4}};
    for (const auto& c : pq)
        for (double K : kCurvatures) {
            geo::PolygonReading r;
            if (geo::measure_polygon(K, c[0], c[1], 1.2, r) != geo::MeasureError::none) continue;
            std::string table, json;
            files::append_polygon_table(table, K, r);
            files::append_polygon_json(json, K, c[0], c[1], 1.2, geo::MeasureError::none, r);
            expect_rows(table, json, rows, heading("polygon", K));
        }
}

// The flat triangle's excess is a rounding error (2.5e-14 degrees, say) and reads 0.0; a value
// just below zero that rounds to it has no sign; one that rounds away from zero keeps its sign.
TEST(MeasureTable, NearZeroHasNoSign) {
    EXPECT_EQ(files::table_number(2.5444437451708134e-14, 1), "0.0");
    EXPECT_EQ(files::table_number(-2.5e-14, 1), "0.0");
    EXPECT_EQ(files::table_number(-0.0, 3), "0.000");
    EXPECT_EQ(files::table_number(-0.0004, 3), "0.000");
    EXPECT_EQ(files::table_number(-0.0006, 3), "-0.001");
    EXPECT_EQ(files::table_number(-149.99999999999997, 1), "-150.0");
    EXPECT_EQ(files::table_number(7, 0), "7");
}

}  // namespace
}  // namespace noneuclid
