# The web page (the `web` preset: Debian's emscripten). The process functions of
# app/platform.hpp a page has (web_platform.cpp), and the page itself: the WebAssembly module
# (page_api.cpp, the display web_display.cpp) with its JavaScript loader, and the page's own
# files, all in build/web/page/, a static folder any web server can serve.
noneuclid_platform_backend(noneuclid_web_platform web/web_platform.cpp)

add_executable(noneuclid_page web/page_api.cpp web/web_display.cpp)
target_link_libraries(noneuclid_page PRIVATE noneuclid_app noneuclid_warnings)
set_target_properties(noneuclid_page PROPERTIES
    OUTPUT_NAME noneuclid
    RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/page)
# A module the page creates (createNoneuclid), for browsers only, whose memory grows with the
# scene (a stress scene, a large canvas); C++ exceptions are caught (a bad option is one
# sentence on the page, as on the command line); the memory file system holds the scene and
# actions files the page hands over.
target_link_options(noneuclid_page PRIVATE
    -sMODULARIZE=1 -sEXPORT_NAME=createNoneuclid -sENVIRONMENT=web -sALLOW_MEMORY_GROWTH=1
    -sEXPORTED_RUNTIME_METHODS=FS,ccall,UTF8ToString -sEXPORTED_FUNCTIONS=_malloc,_free
    -sFILESYSTEM=1 -sINCOMING_MODULE_JS_API=noneuclidPresent,noneuclidReadBack,print,printErr,locateFile)
foreach(file index.html page.js page_lang.js page_fit.js sound.js page.css)
    configure_file(${CMAKE_CURRENT_SOURCE_DIR}/web/page/${file} ${PROJECT_BINARY_DIR}/page/${file} COPYONLY)
endforeach()
