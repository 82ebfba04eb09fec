# Runs bench_map (the C++ det J map of MOMA 3a, 1000×1000 cells) and then the plain NumPy
# version of the same map (moma_map_numpy.py) in one go: prints both times and the speed ratio
# C++/NumPy, and fails if the two maps disagree (reachable cells but for the outline, values to
# 1e-4 relative), if the ratio is below MIN_RATIO (GOAL_RATIO is only reported: met or missed)
# or if C++ misses LIMIT_MS (none by default: the bench_map test has the 5 ms target).
#
#   cmake -DBENCH_MAP=build/bench/bench_map [-DPYTHON=/usr/bin/python3] -DSCRIPT=bench/moma_map_numpy.py
#         -DWORK_DIR=build/bench [-DLIMIT_MS=…] [-DGOAL_RATIO=20] [-DMIN_RATIO=0] [-DRUNS=5]
#         -P bench/map_ratio.cmake

foreach(required BENCH_MAP SCRIPT WORK_DIR)
    if(NOT ${required})
        message(FATAL_ERROR "Give -D${required}=…")
    endif()
endforeach()
if(NOT LIMIT_MS)
    set(LIMIT_MS 1000000) # the 5 ms target is the bench_map test's; here only the ratio counts
endif()
if(NOT MIN_RATIO)
    set(MIN_RATIO 0)
endif()
if(NOT GOAL_RATIO)
    set(GOAL_RATIO 20)
endif()
if(NOT RUNS)
    set(RUNS 5)
endif()

# NumPy first: without it the comparison cannot run, and the message should say what to do.
# python3-numpy installs into Debian's /usr/bin/python3, which need not be the python3 first on
# PATH (pyenv, a virtualenv): take the first interpreter that has NumPy.
set(install_hint "install it with: apt-get install python3-numpy (or run scripts/install-deps.sh)")
set(candidates ${PYTHON} /usr/bin/python3)
set(python "")
foreach(candidate IN LISTS candidates)
    if(NOT EXISTS "${candidate}")
        continue()
    endif()
    execute_process(COMMAND "${candidate}" -c "import numpy; print(numpy.__version__)"
        OUTPUT_VARIABLE numpy_version ERROR_QUIET RESULT_VARIABLE numpy_status OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(numpy_status EQUAL 0)
        set(python "${candidate}")
        break()
    endif()
endforeach()
if(NOT python)
    list(JOIN candidates ", " tried)
    message(FATAL_ERROR "NumPy is missing (tried: ${tried}): ${install_hint}.")
endif()

file(MAKE_DIRECTORY "${WORK_DIR}")
set(values "${WORK_DIR}/moma_map.f32")
set(side "${WORK_DIR}/moma_map.json")
file(REMOVE "${values}" "${side}")

execute_process(COMMAND "${BENCH_MAP}" ${LIMIT_MS} --write "${values}" --json "${side}"
    OUTPUT_VARIABLE cpp_output ERROR_VARIABLE cpp_error RESULT_VARIABLE cpp_status)
message(STATUS "C++ (bench_map):\n${cpp_output}${cpp_error}")
if(NOT EXISTS "${side}" OR NOT EXISTS "${values}")
    message(FATAL_ERROR "bench_map failed (${cpp_status}) before writing its map")
endif()

execute_process(COMMAND "${python}" "${SCRIPT}" --json "${side}" --compare "${values}" --runs ${RUNS}
        --min-ratio ${MIN_RATIO} --goal-ratio ${GOAL_RATIO}
    OUTPUT_VARIABLE numpy_output ERROR_VARIABLE numpy_error RESULT_VARIABLE numpy_status)
message(STATUS "NumPy ${numpy_version}, ${python} (moma_map_numpy.py):\n${numpy_output}${numpy_error}")

if(NOT cpp_status EQUAL 0)
    message(FATAL_ERROR "bench_map failed (${cpp_status}): the C++ map is over its ${LIMIT_MS} ms limit")
endif()
if(NOT numpy_status EQUAL 0)
    message(FATAL_ERROR "moma_map_numpy.py failed (${numpy_status}): see its FAIL lines above")
endif()
