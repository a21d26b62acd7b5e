# The engine's source files, by library, relative to src/: src/CMakeLists.txt builds its
# libraries from these lists and the microcontroller firmware (platform/mcu/CMakeLists.txt) its
# engine, so a new file of a part both use is named here once.
set(noneuclid_fixed_sources fixed/tables.cpp fixed/accuracy.cpp)
set(noneuclid_world_sources world/instruments.cpp world/scenes.cpp world/images.cpp world/game_scene.cpp
    world/budget.cpp world/quote.cpp world/ranges.cpp world/earth.cpp world/sphere_lines.cpp)
# Every file of lang/: the catalogue, and each language's texts and lessons (lang/languages.hpp),
# so that a new language's files need no line here.
file(GLOB noneuclid_lang_sources RELATIVE ${CMAKE_CURRENT_LIST_DIR} CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/lang/*.cpp)
list(SORT noneuclid_lang_sources)
# The rasteriser's part that needs no threads (the firmware's), then the rest.
set(noneuclid_render_core_sources render/raster.cpp render/backdrop.cpp render/fill_rows.cpp render/texture.cpp
    render/hud.cpp render/layout.cpp render/palette.cpp render/font.cpp render/font_builtin.cpp)
set(noneuclid_render_sources ${noneuclid_render_core_sources} render/parallel_frame.cpp render/worker_pool.cpp
    render/measure_panel.cpp)
