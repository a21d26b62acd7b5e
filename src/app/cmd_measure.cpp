// `noneuclid measure INSTRUMENT`: one instrument's readings at one curvature, as one JSON object
// on stdout (files/measure_json.hpp; docs/measure.md explains each instrument), or with
// --format table as rounded rows with their units (files/measure_table.hpp). A construction
// the instrument cannot measure (a mark past the limit circle, coincident or collinear marks, a
// polygon that closes at no K in [-1, 1], a length that is not positive) is one sentence and
// exit status 2, like any bad input.
#include <cstdio>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "files/measure_json.hpp"
#include "files/measure_table.hpp"
#include "geometry/measure.hpp"
#include "world/quote.hpp"

namespace noneuclid::app {

namespace {

std::vector<std::string> instrument_names() {
    std::vector<std::string> names;
    for (geo::Instrument i : geo::kInstruments) names.push_back(geo::instrument_name(i));
    return names;
}

[[noreturn]] void refuse(geo::Instrument i, geo::MeasureError e) {
    usage_error(std::string("measure ") + geo::instrument_name(i) + ": " + geo::measure_error_sentence(e) + ".");
}

}  // namespace

int measure_command(int argc, char** argv, int first) {
    if (first >= argc || argv[first][0] == '-')
        usage_error("measure needs an instrument first: " + world::or_list(instrument_names()) +
                    " (e.g. 'noneuclid measure triangle --curvature 1').");
    Options o = defaults(Command::measure);
    if (!geo::parse_instrument(argv[first], o.measure.instrument))
        usage_error("measure has no instrument '" + std::string(argv[first]) + "': name " +
                    world::or_list(instrument_names()) + ".");
    Args args(argc, argv, first + 1);
    parse_options(args, o, Command::measure);
    const MeasureOptions& m = o.measure;
    const double K = o.curvature;
    std::string out;
    geo::MeasureError e = geo::MeasureError::none;
    switch (m.instrument) {
        case geo::Instrument::triangle: {
            std::vector<geo::Polar<double>> v = m.points;
            if (v.empty()) v = {{1, geo::wrap_pi(1.5707963267948966)}, {1, geo::wrap_pi(3.6651914291880923)}, {1, geo::wrap_pi(5.7595865315812871)}};
            if (v.size() != 3) usage_error("measure triangle: --points needs three points r,deg, not " + std::to_string(v.size()) + ".");
            geo::TriangleReading t;
            e = geo::measure_triangle(K, v.data(), m.limit, t);
            if (e != geo::MeasureError::none) refuse(m.instrument, e);
            if (m.table) files::append_triangle_table(out, K, t);
            else files::append_triangle_json(out, K, v.data(), e, t);
            break;
        }
        case geo::Instrument::circle: {
            geo::CircleReading c;
            e = geo::measure_circle(K, m.centre, m.radius, m.limit, c);
            if (e != geo::MeasureError::none) refuse(m.instrument, e);
            if (m.table) files::append_circle_table(out, K, c);
            else files::append_circle_json(out, K, m.centre, m.radius, e, c);
            break;
        }
        case geo::Instrument::parallels: {
            geo::ParallelsReading p;
            e = geo::measure_parallels(K, m.distance, m.length, p);
            if (e != geo::MeasureError::none) refuse(m.instrument, e);
            if (m.table) files::append_parallels_table(out, K, p);
            else files::append_parallels_json(out, K, m.distance, m.length, e, p);
            break;
        }
        case geo::Instrument::polygon: {
            geo::PolygonReading r;
            e = geo::measure_polygon(K, m.sides, m.around, m.side, r);
            if (e != geo::MeasureError::none) refuse(m.instrument, e);
            if (m.table) files::append_polygon_table(out, K, r);
            else files::append_polygon_json(out, K, m.sides, m.around, m.side, e, r);
            break;
        }
    }
    if (!m.table) out += '\n';  // (a table's rows end in theirs)
    std::fputs(out.c_str(), stdout);
    return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace noneuclid::app
