# Times `pkm sweep pjoint-prototype --var theta --from -60 --to 60 --steps STEPS FORMAT` with
# its output into /dev/null, RUNS times, and fails if the best wall time exceeds LIMIT_SECONDS.
# Self-contained (no hyperfine, no shell): string(TIMESTAMP %f) gives microseconds.
#
#   cmake -DPKM=build/bin/pkm [-DSTEPS=1000000] [-DFORMAT=--csv] [-DLIMIT_SECONDS=1.0] [-DRUNS=3]
#         -P bench/sweep_benchmark.cmake

if(NOT PKM)
    message(FATAL_ERROR "Give the pkm binary: -DPKM=<path>")
endif()
if(NOT STEPS)
    set(STEPS 1000000)
endif()
if(NOT FORMAT)
    set(FORMAT --csv)
endif()
if(NOT LIMIT_SECONDS)
    set(LIMIT_SECONDS 1.0)
endif()
if(NOT RUNS)
    set(RUNS 3)
endif()

# Seconds as text ("1.0") → microseconds as an integer, for math(EXPR).
if(NOT LIMIT_SECONDS MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "LIMIT_SECONDS must be a number of seconds like 1.0, not '${LIMIT_SECONDS}'")
endif()
set(limit_whole "${CMAKE_MATCH_1}")
set(limit_fraction "${CMAKE_MATCH_3}000000")
string(SUBSTRING "${limit_fraction}" 0 6 limit_fraction)
string(REGEX REPLACE "^0+([0-9])" "\\1" limit_fraction "${limit_fraction}") # no octal-looking zeros
math(EXPR limit_us "${limit_whole} * 1000000 + ${limit_fraction}")

function(format_seconds microseconds out)
    math(EXPR whole "${microseconds} / 1000000")
    math(EXPR milli "(${microseconds} % 1000000) / 1000")
    string(LENGTH "${milli}" length)
    if(length EQUAL 1)
        set(milli "00${milli}")
    elseif(length EQUAL 2)
        set(milli "0${milli}")
    endif()
    set(${out} "${whole}.${milli}" PARENT_SCOPE)
endfunction()

set(command "${PKM}" sweep pjoint-prototype --var theta --from -60 --to 60 --steps ${STEPS} ${FORMAT})
list(JOIN command " " shown)
message(STATUS "Benchmark: ${shown} > /dev/null (best of ${RUNS}, limit ${LIMIT_SECONDS} s)")

set(best "")
foreach(run RANGE 1 ${RUNS})
    string(TIMESTAMP start "%s%f" UTC)
    execute_process(COMMAND ${command} OUTPUT_FILE /dev/null ERROR_VARIABLE errors RESULT_VARIABLE status)
    string(TIMESTAMP end "%s%f" UTC)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "pkm failed (${status}): ${errors}")
    endif()
    math(EXPR elapsed "${end} - ${start}")
    format_seconds(${elapsed} seconds)
    message(STATUS "  run ${run}: ${seconds} s")
    if(best STREQUAL "" OR elapsed LESS best)
        set(best ${elapsed})
    endif()
endforeach()

format_seconds(${best} seconds)
if(best GREATER limit_us)
    message(FATAL_ERROR "sweep of ${STEPS} steps took ${seconds} s at best: over the ${LIMIT_SECONDS} s limit")
endif()
message(STATUS "sweep of ${STEPS} steps: ${seconds} s (limit ${LIMIT_SECONDS} s)")
