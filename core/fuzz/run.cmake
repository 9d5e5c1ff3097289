# Runs libFuzzer harnesses briefly, for CTest.
#
#   cmake -DNAMES=spec,sum,... -DBIN_DIR=<dir of fuzz_*> -DCORPUS_ROOT=<seed corpus>
#         -DWORK_ROOT=<scratch dir> [-DCORPUS_POINTS=<fuzz_points' seeds>]
#         [-DSECONDS=18] -P run.cmake
#   cmake -DMISSING="<what to install>" -P run.cmake      (fails with that text)
#
# Each harness fuzz_<name> starts from the seed corpus CORPUS_ROOT/<name>
# (fuzz_points from CORPUS_POINTS: its seeds live beside its source)
# (read only: new inputs go to WORK_ROOT/<name>), with a fixed seed, and stops
# after SECONDS seconds (18 by default: about 20 with start-up and the final
# pass) or 2,000,000 inputs, whichever comes first. A crash,
# a sanitizer report or a failed check exits non-zero and leaves the input in
# WORK_ROOT as <name>-crash-*.
if(DEFINED MISSING)
  message(FATAL_ERROR "${MISSING}")
endif()
if(NOT DEFINED SECONDS)
  set(SECONDS 18)
endif()
string(REPLACE "," ";" names "${NAMES}")
foreach(name IN LISTS names)
  set(exe "${BIN_DIR}/fuzz_${name}")
  set(work "${WORK_ROOT}/${name}")
  if(NOT EXISTS "${exe}")
    message(FATAL_ERROR "fuzz harness ${exe} was not built")
  endif()
  file(MAKE_DIRECTORY "${work}")
  set(seeds "${CORPUS_ROOT}/${name}")
  if(name STREQUAL "points")
    set(seeds "${CORPUS_POINTS}")
  endif()
  # the longest input worth trying: a SPEC line, a pair's bytes (fuzz_collide
  # reads 61), or a few dozen lines of a file
  set(maxlen 2048)
  if(name STREQUAL "spec")
    set(maxlen 256)
  elseif(name STREQUAL "collide")
    set(maxlen 64)
  endif()
  execute_process(
    COMMAND "${exe}" -seed=1 -max_total_time=${SECONDS} -runs=2000000 -max_len=${maxlen}
            -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
            "-artifact_prefix=${WORK_ROOT}/${name}-" "${work}" "${seeds}"
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
  # libFuzzer reports on stderr; keep its summary lines and any failure.
  string(REGEX MATCHALL "(stat::[a-z_]+:[^\n]*|Done [^\n]*|fuzz_[a-z]+: [^\n]*|==[0-9]+==ERROR[^\n]*|SUMMARY[^\n]*|[^\n]*runtime error[^\n]*)" lines "${err}")
  string(REPLACE ";" "\n  " lines "${lines}")
  message("fuzz_${name}:\n  ${lines}")
  if(NOT rc EQUAL 0)
    message("${err}")
    message(FATAL_ERROR "fuzz_${name} failed (exit ${rc}); the input is in ${WORK_ROOT}")
  endif()
endforeach()
