# The CTest smoke run (cmake -P): fuzz for SECONDS from the seed corpus and the regressions.
# libFuzzer writes new inputs only into its first folder, so that one is a fresh folder under WORK and
# the repository's folders are read, never changed. A crash, a hang (over 10 s), running out of memory
# (2 GiB) or a sanitizer report fails the test; the input is left under WORK/crashes/.
# Variables: FUZZER (the gltf_fuzz executable), SOURCE (tests/fuzz), WORK (a scratch folder), SECONDS.
foreach(var FUZZER SOURCE WORK SECONDS)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "smoke.cmake: -D${var}=... is missing")
    endif()
endforeach()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/crashes)
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1")
execute_process(
    COMMAND ${FUZZER} ${WORK}/corpus ${SOURCE}/corpus ${SOURCE}/regressions
            -dict=${SOURCE}/gltf.dict -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
            -artifact_prefix=${WORK}/crashes/ -print_final_stats=1
    WORKING_DIRECTORY ${WORK}
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    file(GLOB found ${WORK}/crashes/*)
    message(FATAL_ERROR "gltf_fuzz failed (exit ${result}); inputs: ${found}")
endif()
