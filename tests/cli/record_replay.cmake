# `noneuclid run --display png --record R` (the headless display, keys from an actions file),
# then `noneuclid render --actions R`: the same picture, pixel for pixel (png_diff --exact).
# With -DRUN_DIR=D the run is made in D (SCENE then a path relative to it, as typed there) and
# replayed from DIR: the recording names the scene so that it replays anywhere, and the HUD (on in
# a run) shows the same words in both.
#   cmake -DNONEUCLID=... -DPNG_DIFF=... -DSCENE=... -DACTIONS=... -DDIR=... [-DRUN_DIR=...] -P record_replay.cmake
file(MAKE_DIRECTORY ${DIR})
set(rec ${DIR}/recording.txt)
if(NOT DEFINED RUN_DIR)
    set(RUN_DIR ${DIR})
endif()
execute_process(COMMAND ${NONEUCLID} run --display png --scene ${SCENE} --actions ${ACTIONS} --frames 150
                        --size 400x300 --aa --record ${rec} --screenshot ${DIR}/run.png
                WORKING_DIRECTORY ${RUN_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run failed (${rc}): ${err}")
endif()
file(READ ${rec} text)
foreach(want "scene " "aa on" "size 400x300" "frames 150" "press thrust")
    string(FIND "${text}" "${want}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "the recording has no '${want}':\n${text}")
    endif()
endforeach()
execute_process(COMMAND ${NONEUCLID} render --actions ${rec} --out ${DIR}/replay.png
                WORKING_DIRECTORY ${DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${PNG_DIFF} ${DIR}/run.png ${DIR}/replay.png --exact RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the replay differs from the run: ${out}")
endif()
# The comparison can fail: the same recording without its thrust differs.
string(REGEX REPLACE "[0-9.]+ press thrust\n" "" without "${text}")
file(WRITE ${DIR}/without.txt "${without}")
execute_process(COMMAND ${NONEUCLID} render --actions ${DIR}/without.txt --out ${DIR}/without.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
execute_process(COMMAND ${PNG_DIFF} ${DIR}/run.png ${DIR}/without.png --exact RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 1)
    message(FATAL_ERROR "without the thrust the replay should differ: ${out}")
endif()
message(STATUS "run and replay: ${out}")
