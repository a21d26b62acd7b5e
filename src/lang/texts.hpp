// Every text the program shows a user in words (the HUD, the legends, the instruments' panel,
// the lessons' words, the worksheet, the web page), by name, with its English: the catalogue's
// index. Each language's file (de.cpp, fr.cpp) gives every name its text; tests/lang checks
// that none is missing and that each keeps the English's printf conversions, in order.
//
// X(name, english). A name starting page_ is the web page's (the page asks for them by name).
#pragma once

#define NONEUCLID_TEXTS(X)                                                                          \
    /* the HUD */                                                                                   \
    X(spherical, "spherical")                                                                       \
    X(flat, "flat")                                                                                 \
    X(hyperbolic, "hyperbolic")                                                                     \
    X(score, "SCORE %ld")                                                                           \
    X(score_new_best, "SCORE %ld  NEW BEST")                                                        \
    X(best, "BEST %ld")                                                                             \
    X(level, "LEVEL %d")                                                                            \
    X(press_fire, "PRESS FIRE")                                                                     \
    X(game_over, "GAME OVER")                                                                       \
    X(view_km, "view %.0f km")                                                                      \
    X(view_km_least, "view %.0f km: as close as the zoom goes")                                     \
    X(view_km_most, "view %.0f km: the whole globe")                                                \
    /* the projections, as the HUD names them */                                                   \
    X(equidistant, "equidistant")                                                                   \
    X(stereographic, "stereographic")                                                               \
    X(gnomonic, "gnomonic")                                                                         \
    X(orthographic, "orthographic")                                                                 \
    X(lambert, "lambert")                                                                           \
    /* an uneven world's two views, and its bumps' gain (src/uneven) */                            \
    X(view_chart, "chart")                                                                          \
    X(view_inhabitant, "inhabitant's view")                                                         \
    X(view_map, "map")  /* the 3D world's map: the ball seen from outside */                          \
    /* a honeycomb's fit (src/space/honeycomb.hpp): its name, its cubes round an edge, the K */      \
    X(honeycomb_fits, "%s: %d cubes round each edge fit: K = %+.3f")                                 \
    X(honeycomb_gap, "%s: %d cubes round an edge leave %+.1f degrees; it closes at K = %+.3f")           \
    X(honeycomb_none, "%s: no such cube at this K; it closes at K = %+.3f")                          \
    X(bump_gain, "bumps x%.2f")                                                                     \
    /* the legends: the desktop's keys, the kiosk's buttons, the zoom's, one button, attract */    \
    X(legend_keys, "arrows/WASD  Space fire  +/- K  1 2 3 K=-1,0,1  P projection  M measure  H HUD  R reset  Esc") \
    X(legend_buttons, "thrust  left/right  fire  curvature +/-  preset  reset")                     \
    X(legend_buttons_no_fire, "thrust  left/right  curvature +/-  preset  reset")                   \
    X(legend_zoom_keys, "arrows/WASD  +/- zoom  1 2 3 K=-1,0,1  P projection  M measure  H HUD  R reset  Esc") \
    X(legend_uneven_keys, "arrows/WASD  +/- K  < > bumps  1 2 3 K=-1,0,1  P view  H HUD  R reset  Esc") \
    X(legend_uneven_game_keys, "arrows/WASD  Space fire  +/- K  < > bumps  1 2 3 K=-1,0,1  P view  H HUD  R reset  Esc") \
    X(legend_space_keys, "arrows/WASD  I K pitch  Q E roll  +/- K  1 2 3 K=-1,0,1  P view  H HUD  R reset  Esc") \
    X(legend_space_buttons, "thrust  left/right  curvature +/-  fire+left/right roll  fire+curvature pitch") \
    X(legend_zoom_buttons, "thrust  left/right  zoom +/-  preset  reset")                           \
    X(legend_one_button_game, "one button: hold fire to thrust, tap to fire")                       \
    X(legend_one_button, "one button: hold fire to thrust, tap for the next K")                     \
    X(legend_attract, "attract mode: press any button to fly")                                      \
    X(legend_attract_game, "attract mode: press fire to play")                                      \
    /* the instruments' panel */                                                                    \
    X(instrument_triangle, "triangle")                                                              \
    X(instrument_circle, "circle")                                                                  \
    X(instrument_parallels, "parallels")                                                            \
    X(instrument_polygon, "polygon")                                                                  \
    X(mark_of, "fire: mark %d")                                                                     \
    X(of_needed, "of %d")                                                                           \
    X(angle_sum, "sum")                                                                             \
    X(label_excess, "exc")  /* a triangle's angular excess, on the panel (three or four letters) */ \
    X(label_area, "area")   /* its area */                                                      \
    X(label_ratio, "ratio") /* the parallels' ratio of distances (five letters at most) */         \
    X(label_meet, "meet")   /* where the parallels meet (four letters at most) */               \
    X(label_angle, "ang")   /* a polygon's angle */                                             \
    X(label_gap, "gap")     /* what its angles leave of 360 degrees at a vertex */              \
    X(label_over, "over")   /* what they pass 360 degrees by */                                 \
    X(closes_at, "closes at")                                                                       \
    X(unit_length, "u")   /* the world's unit of length (K = +1: the sphere of radius 1) */         \
    X(unit_area, "u²")    /* its square */                                                          \
    /* lessons: what ends a step, the worksheet */                                                  \
    X(done_fire, "press fire to go on")                                                             \
    X(done_above, "K above %g")                                                                     \
    X(done_below, "K below %g")                                                                     \
    X(done_score, "a score of %g")                                                                  \
    X(question, "Question: %s")                                                                     \
    X(worksheet_name, "Name:")                                                                      \
    X(worksheet_step, "%d. K = %+.2f, %s")                                                          \
    X(worksheet_readings, "Measure at K = %+.2f:")                                                  \
    X(worksheet_key, "Key")       /* where a pupil's page has "Name:" */                            \
    X(worksheet_page, "page %d of %d")                                                              \
    /* the web page */                                                                              \
    X(page_title, "space of constant curvature K, from −1 (hyperbolic) through 0 (flat) to +1 (spherical)") \
    X(page_scene, "scene")                                                                          \
    X(page_engine, "engine")                                                                        \
    X(page_projection, "projection")                                                                \
    X(page_stop, "stop")                                                                            \
    X(page_restart, "start again")                                                                  \
    X(page_full_screen, "full screen")                                                              \
    X(page_leave_full_screen, "leave full screen")                                                  \
    X(page_download, "download the recording")                                                      \
    X(page_own_scene, "your own scene (TOML)")                                                      \
    X(page_run_scene, "run this scene")                                                             \
    X(page_or, "or")                                                                                \
    X(page_help, "Keys: arrows or WASD fly, + and − (or ] and [) bend space, 1 2 3 set K to −1, 0, +1, P the next projection, H the HUD, N mutes the sound, R reset, Esc ends the run.") \
    X(page_help_game, "Keys: arrows or WASD fly, Space fires, + and − (or ] and [) bend space, 1 2 3 set K to −1, 0, +1, P the next projection, H the HUD, N mutes the sound, R reset, Esc ends the run.") \
    X(page_help_bumps, "< and > turn the bumps of this uneven world.")                           \
    X(page_loading, "loading…")                                                                     \
    X(page_not_running, "not running")                                                              \
    X(page_ended, "ended")                                                                          \
    X(page_status, "frame %d · K = %s · %s · %s engine · %s ms a frame")                            \
    X(page_thrust, "▲ thrust")                                                                      \
    X(page_left, "◀ left")                                                                          \
    X(page_right, "right ▶")                                                                        \
    X(page_preset, "preset K")                                                                      \
    X(page_fire, "fire")                                                                            \
    X(page_language, "language")                                                                    \
    X(page_sound_on, "sound: on")                                                                   \
    X(page_sound_off, "sound: off")
