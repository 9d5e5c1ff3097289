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

# mk_shard_test(NAME EXE ARGS SHARDS [DROP_COLUMNS I ...]): the run split
# into SHARDS shards, concatenated under one header, is byte for byte the
# unsplit run (ARGS a ";"-list); DROP_COLUMNS (0-based) are left out of the
# comparison first: measured times, which differ from run to run.
function(mk_shard_test name exe args shards)
  cmake_parse_arguments(PARSE_ARGV 4 mks "" "" "DROP_COLUMNS")
  string(REPLACE ";" "," drop "${mks_DROP_COLUMNS}")
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=${exe} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/${name}.work
      "-DARGS=${args}" -DSHARDS=${shards} "-DDROP=${drop}" -P ${MINK_EXP_TESTING_DIR}/shard_concat.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT ${MINK_T120})
endfunction()

# mk_expect_usage_errors(TARGET NAME ARGS REGEX [NAME ARGS REGEX ...]): one
# mk_expect_usage_error test TARGET.badflag.NAME per triple, for a driver's
# table of its own bad flags.
function(mk_expect_usage_errors target)
  set(rest ${ARGN})
  list(LENGTH rest n)
  while(n GREATER 2)
    list(POP_FRONT rest name args expect)
    mk_expect_usage_error(${target}.badflag.${name} $<TARGET_FILE:${target}> "${args}" "${expect}")
    list(LENGTH rest n)
  endwhile()
  if(NOT n EQUAL 0)
    message(FATAL_ERROR "mk_expect_usage_errors(${target}): arguments come in triples NAME ARGS REGEX")
  endif()
endfunction()

# mk_expect_failure(NAME EXE ARGS REGEX [PREPARE FILE CONTENT TEXT]): a
# run-time failure: EXE with ARGS ("|"-separated) exits 1 with nothing on
# stdout and one line on stderr matching REGEX. PREPARE writes FILE first
# with TEXT ("|" for line breaks).
function(mk_expect_failure name exe args expect)
  cmake_parse_arguments(PARSE_ARGV 4 mkf "" "PREPARE;CONTENT" "")
  set(prepare "")
  if(mkf_PREPARE)
    set(prepare -DPREPARE=${mkf_PREPARE} "-DCONTENT=${mkf_CONTENT}")
  endif()
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=${exe} "-DARGS=${args}" "-DEXPECT=${expect}" -DSTATUS=1 ${prepare}
      -P ${MINK_EXP_TESTING_DIR}/expect_usage_error.cmake)
endfunction()

# mk_plot_test(NAME SCRIPT RESULTS FIXTURE): gnuplot draws RESULTS (a CSV
# that the test fixture FIXTURE writes) with plots/SCRIPT into RESULTS'
# folder, from the top of the project as Makefile.paper runs it; not
# registered (and said so) when gnuplot is missing.
function(mk_plot_test name script results fixture)
  find_program(MK_GNUPLOT gnuplot)
  if(NOT MK_GNUPLOT)
    message(STATUS "gnuplot not found: the ${name} test is not registered")
    return()
  endif()
  get_filename_component(outdir ${results} DIRECTORY)
  add_test(NAME ${name} COMMAND ${MK_GNUPLOT} -e "results='${results}'; outdir='${outdir}'"
    ${PROJECT_SOURCE_DIR}/plots/${script})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${fixture} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endfunction()

# mk_summary_test(NAME LIBRARY SOURCE): a test program SOURCE linking
# LIBRARY that writes an experiment's summary into a scratch folder it gets
# as its argument, registered as NAME.
function(mk_summary_test name library source)
  string(REPLACE "." "_" exe "test_${name}")
  add_executable(${exe} ${source})
  target_compile_options(${exe} PRIVATE ${MINK_C_WARNINGS})
  target_link_libraries(${exe} PRIVATE ${library} mink_ensure)
  target_include_directories(${exe} PRIVATE ${MINK_EXP_TESTING_DIR})
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/${name}.work)
  add_test(NAME ${name} COMMAND ${exe} ${CMAKE_CURRENT_BINARY_DIR}/${name}.work)
endfunction()
