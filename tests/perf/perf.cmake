# Performance (issue 8): the geometry and frame benchmarks, the frame-breakdown and scaling
# benchmarks, the instruction-count frame probe, and the tests that keep the fast paths honest
# (exact division kernels, the threaded frame identical to one thread). Included from
# tests/CMakeLists.txt.
find_package(Threads REQUIRED)

if(NONEUCLID_HAVE_BENCHMARK)
    foreach(b bench_geometry bench_breakdown bench_scaling bench_parallel bench_fill)
        add_executable(${b} bench/${b}.cpp)
        target_link_libraries(${b} PRIVATE benchmark::benchmark noneuclid_render noneuclid_warnings Threads::Threads)
    endforeach()
    target_link_libraries(bench_frame PRIVATE Threads::Threads)
    if(NOT CMAKE_CROSSCOMPILING)
        add_test(NAME bench_geometry_smoke
            COMMAND bench_geometry --benchmark_min_time=0.001 --benchmark_filter=kiosk)
        set_tests_properties(bench_geometry_smoke PROPERTIES LABELS bench)
        # Filled and textured bodies against a memset (docs/performance.md): runs, and its table.
        add_test(NAME bench_fill_smoke
            COMMAND bench_fill --benchmark_min_time=0.001 --benchmark_filter=800x480_rgb565/fixed)
        set_tests_properties(bench_fill_smoke PROPERTIES LABELS bench PASS_REGULAR_EXPRESSION "\\| 800x480_rgb565 \\| fixed \\| [1-9]")
    endif()
endif()

# One thread against two, interleaved in one process (docs/performance.md): a plain program.
add_executable(parallel_ab bench/parallel_ab.cpp)
target_link_libraries(parallel_ab PRIVATE noneuclid_render noneuclid_warnings Threads::Threads)

# Frames for instruction counting under qemu-user (tests/bench/arm-frame-insncount.sh): a
# plain program, static when cross-compiling.
add_executable(frame_probe bench/frame_probe.cpp)
target_link_libraries(frame_probe PRIVATE noneuclid_render noneuclid_warnings Threads::Threads)
if(CMAKE_CROSSCOMPILING)
    target_link_options(frame_probe PRIVATE -static)
endif()

# The fast paths give the same bits as the plain arithmetic; the threaded frame the same pixels
# as one thread, for every engine.
add_executable(perf_tests fixed/test_division.cpp render/test_edge_paths.cpp render/test_fixed_equidistant.cpp
    render/test_raster_paths.cpp render/test_parallel.cpp)
target_link_libraries(perf_tests PRIVATE GTest::gtest_main noneuclid_render noneuclid_warnings Threads::Threads)
gtest_discover_tests(perf_tests DISCOVERY_TIMEOUT 120 PROPERTIES LABELS perf)
target_link_libraries(no_alloc_tests PRIVATE Threads::Threads)
# The threaded tests start threads. Under qemu-user (Debian 12's 7.2) a dynamically linked
# program that starts a thread hangs (aarch64) or crashes (armhf) before the thread runs; the
# same program linked statically runs. So the cross builds link these statically, as
# insn_probe and frame_probe already are.
if(CMAKE_CROSSCOMPILING)
    target_link_options(perf_tests PRIVATE -static)
    target_link_options(no_alloc_tests PRIVATE -static)
endif()
