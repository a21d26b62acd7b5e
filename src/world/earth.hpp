// The Earth as a scene (docs/earth.md): Natural Earth's coastlines (world/earth_data.hpp) and a
// graticule every 15 degrees, as polylines about a chosen centre. A place at latitude and
// longitude is put at its angular distance r from the centre and its bearing: theta = 90 degrees
// minus the azimuth (east of north), so north is up and east to the right at the centre. At
// K = +1 that is the unit sphere itself (the antipode at r = pi, the limit circle); at other K
// each point keeps its distance and bearing: the flat azimuthal equidistant map at K = 0, a
// hyperbolic Earth at K < 0.
#pragma once

#include <string>

#include "world/scene.hpp"

namespace noneuclid::world {

// A place's polar coordinates about the centre (lat0, lon0), all in degrees: r in radians of
// the unit sphere (0 to pi), theta in degrees.
struct EarthPolar {
    double r = 0, theta_deg = 0;
};
EarthPolar earth_polar(double lat0, double lon0, double lat, double lon);

// "LAT,LON" (degrees, |LAT| <= 90, |LON| <= 180) into lat and lon; false if it is not two
// such numbers.
bool parse_centre(const std::string& text, double& lat, double& lon);

// The Earth's mean radius, km, and the views --view takes: from a city to the antipode (half
// the circumference, pi times the radius, where K = 1).
inline constexpr double kEarthRadiusKm = 6371;
inline constexpr double kEarthViewMinKm = 10, kEarthViewMaxKm = 3.14159265358979323846 * kEarthRadiusKm;

// The curvature at which the screen's radius (the limit radius pi) shows view_km of an Earth of
// kEarthRadiusKm: the Earth is then the sphere of that curvature, of radius 1 / sqrt K world
// units, so a world unit is kEarthRadiusKm sqrt K km and pi of them are view_km:
// K = (view_km / (pi kEarthRadiusKm))^2 (docs/earth.md).
double earth_view_curvature(double view_km);

// Tissot's indicatrices (--tissot): geodesic circles of this radius about the places of a grid
// every kTissotGridDeg degrees (latitudes -60 to 60, longitudes -180 to 150, and the poles).
// Drawn by a projection, each is an ellipse whose axes are that projection's scale factors there.
inline constexpr double kTissotRadiusKm = 500;
inline constexpr int kTissotGridDeg = 30;

// The earth scene about the centre (lat0, lon0), limit radius pi, the graticule and the
// coastlines as grid bodies (a backdrop: their edges are short, docs/earth.md). view_km 0: the
// whole globe at K = +1, a place at its angle from the centre. Else zoomed: K from
// earth_view_curvature, a place at its distance on that sphere (its angle / sqrt K), and only
// the lines within the view (and just past its edge) kept. tissot: Tissot's circles too.
// bend false: edges halved only to keep them short, for the sphere of the scene's own K alone
// (where the great circles are the geodesics), not by the bend bound that keeps them on the
// Earth's lines at every K.
void earth_scene(Scene& s, double lat0, double lon0, double view_km = 0, bool tissot = false, bool bend = true);

// The built-in earth scene: earth_scene's lines at several zooms (Scene::zoom's levels: the
// whole globe, then kEarthZoomFirstKm and each half the last down to kEarthViewMinKm, and
// view_km's own), so that the curvature keys zoom live from the globe to a town
// (docs/earth.md): a level shown down to half its view has its lines simplified to a pixel at
// most. It starts at view_km (0: the globe).
inline constexpr double kEarthZoomFirstKm = 10000;
void earth_zoom_scene(Scene& s, double lat0, double lon0, double view_km = 0, bool tissot = false);

}  // namespace noneuclid::world
