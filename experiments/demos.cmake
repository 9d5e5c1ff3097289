# demos.cmake - the drivers of the paper's demonstration figures 1-4 (demos)
# and of the C-obstacle experiment, Table 2 and Fig. 9 (cobstacle), with
# their tests. Included from experiments/CMakeLists.txt.

# demos: the geometry of figures 1-4 as CSV, exactly the paper's parameters.
add_executable(demos ${CMAKE_CURRENT_LIST_DIR}/demos.c)
target_link_libraries(demos PRIVATE mink_exp m)
target_compile_options(demos PRIVATE ${MINK_C_WARNINGS})

# cobstacle: C-obstacle timings (Table 2) and the geometry of Fig. 9.
add_executable(cobstacle ${CMAKE_CURRENT_LIST_DIR}/cobstacle.c)
target_link_libraries(cobstacle PRIVATE mink_exp m)
target_compile_options(cobstacle PRIVATE ${MINK_C_WARNINGS})

if(MINK_BUILD_TESTS)
  set(mkdemos_tests ${CMAKE_CURRENT_LIST_DIR}/demos_tests)
  set(mkdemos_work ${CMAKE_CURRENT_BINARY_DIR}/demos_tests)
  set(mkusage ${CMAKE_CURRENT_LIST_DIR}/common/tests/expect_usage_error.cmake)

  # Bad flags: one line naming the flag and its range, exit status 2.
  # Arguments are separated by "|".
  function(mk_demos_badflag exe name args expect)
    add_test(NAME ${exe}.badflag.${name}
      COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:${exe}> "-DARGS=${args}"
        "-DEXPECT=${expect}" -P ${mkusage})
  endfunction()
  mk_demos_badflag(demos figure "--figure|5" "^demos: --figure: expected one of 1[|]2[|]3[|]4[|]all, got '5'$")
  mk_demos_badflag(demos outline "--outline|7" "^demos: --outline: expected an integer in \\[8, 100000\\], got '7'$")
  mk_demos_badflag(demos impl "--impl|neon" "^demos: --impl: expected one of auto[|]scalar[|]avx2[|]avx512, got 'neon'$")
  mk_demos_badflag(demos trials "--trials|2" "^demos: --trials: expected an integer in \\[1, 1\\], got '2'$")
  mk_demos_badflag(demos shard "--shard|4/4" "^demos: --shard: expected I/N")
  mk_demos_badflag(demos unknown "--grid|5" "^demos: --grid: unknown option")
  mk_demos_badflag(demos missing "--out" "^demos: --out: missing value")
  mk_demos_badflag(demos forcevalue "--force=yes" "^demos: --force: takes no value$")
  mk_demos_badflag(cobstacle trials "--trials|0" "^cobstacle: --trials: expected an integer in \\[1, 1000000\\], got '0'$")
  mk_demos_badflag(cobstacle levels "--obstacles2|50,,10" "^cobstacle: --obstacles2: expected up to 16 comma-separated integers in \\[1, 10000000\\], got '50,,10'$")
  mk_demos_badflag(cobstacle levelzero "--obstacles3|0" "^cobstacle: --obstacles3: expected up to 16")
  mk_demos_badflag(cobstacle dim "--dim|4" "^cobstacle: --dim: expected one of 2[|]3[|]both, got '4'$")
  mk_demos_badflag(cobstacle form "--form|paper" "^cobstacle: --form: expected one of normal[|]gradient, got 'paper'$")
  mk_demos_badflag(cobstacle points "--points|2" "^cobstacle: --points: expected an integer in \\[3, 100000\\], got '2'$")
  mk_demos_badflag(cobstacle grid "--grid|1" "^cobstacle: --grid: expected an integer in \\[2, 1000\\], got '1'$")
  mk_demos_badflag(cobstacle slices "--headings|8|--fig-slices|9" "^cobstacle: --fig-slices: expected an integer in \\[1, 8\\] \\(the headings\\), got '9'$")
  mk_demos_badflag(cobstacle seed "--seed|-1" "^cobstacle: --seed: expected an integer in \\[0, 2\\^64-1\\]")
  mk_demos_badflag(cobstacle unknown "--bogus|1" "^cobstacle: --bogus: unknown option")

  # Run-time failures: a missing or malformed rotations file, or fewer
  # rotations than asked for; exit status 1 and a message.
  function(mk_demos_fails name args expect)
    add_test(NAME cobstacle.fails.${name}
      COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:cobstacle> "-DARGS=${args}" "-DEXPECT=${expect}"
        ${ARGN} -P ${mkdemos_tests}/expect_failure.cmake)
  endfunction()
  file(MAKE_DIRECTORY ${mkdemos_work})
  set(mkc_small "--dim|3|--trials|1|--obstacles3|2|--fig-obstacles|0|--force")
  mk_demos_fails(nofile "${mkc_small}|--so3|${mkdemos_work}/absent.csv|--out|${mkdemos_work}/f1.csv"
    "--so3: cannot open '.*absent.csv'")
  mk_demos_fails(notrotation "${mkc_small}|--so3|${mkdemos_work}/bad_rot.csv|--out|${mkdemos_work}/f2.csv"
    "bad_rot.csv:2: not a rotation matrix" -DPREPARE=${mkdemos_work}/bad_rot.csv
    "-DCONTENT=r11,r12,r13,r21,r22,r23,r31,r32,r33|1,0,0,0,1,0,0,0,2|")
  mk_demos_fails(badrow "${mkc_small}|--so3|${mkdemos_work}/bad_row.csv|--out|${mkdemos_work}/f3.csv"
    "bad_row.csv:2: expected nine comma-separated numbers" -DPREPARE=${mkdemos_work}/bad_row.csv
    "-DCONTENT=r11,r12,r13,r21,r22,r23,r31,r32,r33|1,0,0,0,1,0|")
  mk_demos_fails(tooshort "${mkc_small}|--so3|${CMAKE_CURRENT_LIST_DIR}/data/so3_double_coset_3600.csv|--orientations|3601|--out|${mkdemos_work}/f4.csv"
    "--orientations: 3601 requested, but '.*' holds only 3600")

  # demos: the whole run (under a second), then its geometry against the
  # bodies' implicit functions; and shards of it, whose index rows
  # concatenate to the unsplit run's.
  add_executable(test_demos ${mkdemos_tests}/test_demos.c)
  target_include_directories(test_demos PRIVATE ${CMAKE_CURRENT_LIST_DIR}/common/tests)
  target_link_libraries(test_demos PRIVATE mink::core mink_ensure m)
  target_compile_options(test_demos PRIVATE ${MINK_C_WARNINGS})
  add_test(NAME demos.run COMMAND demos --force --out ${mkdemos_work}/run/demos.csv)
  set_tests_properties(demos.run PROPERTIES FIXTURES_SETUP demos_run)
  add_test(NAME demos.geometry COMMAND test_demos ${mkdemos_work}/run/demos.csv)
  set_tests_properties(demos.geometry PROPERTIES FIXTURES_REQUIRED demos_run)
  # An existing result is kept unless --force is given.
  add_test(NAME demos.noforce
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:demos> "-DARGS=--out|${mkdemos_work}/run/demos.csv"
      "-DEXPECT=demos.csv exists; pass --force to replace it" -P ${mkdemos_tests}/expect_failure.cmake)
  set_tests_properties(demos.noforce PROPERTIES FIXTURES_REQUIRED demos_run)
  add_test(NAME demos.shards
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:demos> -DWORK=${mkdemos_work}/shards
      "-DARGS=--figure;all" -DSHARDS=3 -P ${CMAKE_CURRENT_LIST_DIR}/common/tests/shard_concat.cmake)

  # cobstacle: a small run (both dimensions, two trials, a 20-obstacle
  # figure scene), its rows and the figure's C-obstacles against support
  # functions; and shards, equal to the unsplit run but for the timings.
  add_executable(test_cobstacle ${mkdemos_tests}/test_cobstacle.c)
  target_include_directories(test_cobstacle PRIVATE ${CMAKE_CURRENT_LIST_DIR}/common/tests)
  target_link_libraries(test_cobstacle PRIVATE mink_ensure m)
  target_compile_options(test_cobstacle PRIVATE ${MINK_C_WARNINGS})
  set(mkc_args --trials 2 --obstacles2 3,7 --obstacles3 4 --headings 10 --points 12 --grid 4
    --orientations 6 --so3 ${CMAKE_CURRENT_LIST_DIR}/data/so3_double_coset_3600.csv
    --fig-obstacles 25 --fig-slices 5 --seed 77)
  add_test(NAME cobstacle.run COMMAND cobstacle ${mkc_args} --force --out ${mkdemos_work}/cob/cobstacle.csv)
  set_tests_properties(cobstacle.run PROPERTIES FIXTURES_SETUP cobstacle_run)
  add_test(NAME cobstacle.check COMMAND test_cobstacle ${mkdemos_work}/cob/cobstacle.csv 6)
  set_tests_properties(cobstacle.check PROPERTIES FIXTURES_REQUIRED cobstacle_run)
  add_test(NAME cobstacle.noforce
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:cobstacle> "-DARGS=--out|${mkdemos_work}/cob/cobstacle.csv"
      "-DEXPECT=cobstacle.csv exists; pass --force to replace it" -P ${mkdemos_tests}/expect_failure.cmake)
  set_tests_properties(cobstacle.noforce PROPERTIES FIXTURES_REQUIRED cobstacle_run)
  add_test(NAME cobstacle.shards
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:cobstacle> -DWORK=${mkdemos_work}/cob_shards
      "-DARGS=--trials;2;--obstacles2;3,7;--obstacles3;4;--headings;10;--points;12;--grid;4;--orientations;6;--so3;${CMAKE_CURRENT_LIST_DIR}/data/so3_double_coset_3600.csv;--fig-obstacles;0;--seed;77"
      -DSHARDS=4 -P ${mkdemos_tests}/cobstacle_shards.cmake)

  # The plot scripts draw the small runs' results (they read results only).
  find_program(MKDEMOS_GNUPLOT gnuplot)
  if(MKDEMOS_GNUPLOT)
    add_test(NAME demos.plot COMMAND ${MKDEMOS_GNUPLOT} -e "results='${mkdemos_work}/run/demos.csv'; outdir='${mkdemos_work}/run'"
      ${PROJECT_SOURCE_DIR}/plots/demos.gp)
    set_tests_properties(demos.plot PROPERTIES FIXTURES_REQUIRED demos_run WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    add_test(NAME cobstacle.plot COMMAND ${MKDEMOS_GNUPLOT} -e "results='${mkdemos_work}/cob/cobstacle.csv'; outdir='${mkdemos_work}/cob'"
      ${PROJECT_SOURCE_DIR}/plots/cobstacle.gp)
    set_tests_properties(cobstacle.plot PROPERTIES FIXTURES_REQUIRED cobstacle_run WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  else()
    message(STATUS "gnuplot not found: the demos.plot and cobstacle.plot tests are not registered")
  endif()
endif()
