# testing.cmake - CTest helpers every experiment's tests use (included by
# experiments/CMakeLists.txt before the experiments).

# mk_expect_usage_error(NAME EXE ARGS REGEX): running EXE with ARGS
# ("|"-separated; a ";" would split the test command) exits 2 with nothing
# on stdout and exactly one line on stderr that matches REGEX.
function(mk_expect_usage_error name exe args expect)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=${exe} "-DARGS=${args}" "-DEXPECT=${expect}"
      -P ${MINK_EXP_TESTING_DIR}/expect_usage_error.cmake)
endfunction()

# mk_shard_test(NAME EXE ARGS SHARDS [UNTIMED COLUMN...]): the run split
# into SHARDS shards, concatenated under one header, is byte for byte the
# unsplit run (ARGS a ";"-list), once the measured columns given after
# UNTIMED (0-based indices) are emptied in both.
function(mk_shard_test name exe args shards)
  cmake_parse_arguments(PARSE_ARGV 4 mk "" "" "UNTIMED")
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=${exe} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/${name}.work
      "-DARGS=${args}" -DSHARDS=${shards} "-DUNTIMED=${mk_UNTIMED}"
      -P ${MINK_EXP_TESTING_DIR}/shard_concat.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT 120)
endfunction()
