# collision.cmake - the collision-detection driver `collision` (paper
# Sec. 7.2, Table 3) and its tests.
#
# Included from experiments/CMakeLists.txt it adds the target and registers
# the tests. Run as a script (cmake -DMODE=... -P collision.cmake) it is the
# body of the tests that need more than one command: MODE=tiny or shards.

if(NOT CMAKE_SCRIPT_MODE_FILE)

if(NOT TARGET mink_collide)
  message(STATUS "collision: the collision queries are not built (MINK_BUILD_BASELINES=OFF); no collision driver")
else()
  add_executable(collision ${CMAKE_CURRENT_LIST_DIR}/collision.c)
  target_link_libraries(collision PRIVATE mink_collide mink_exp m)
  target_compile_options(collision PRIVATE ${MINK_C_WARNINGS})

  if(MINK_BUILD_TESTS)
    set(mk_collision_script ${CMAKE_CURRENT_LIST_DIR}/collision.cmake)
    # Bad flags: a one-line error naming the flag and its range, exit 2.
    function(mk_collision_badflag name args expect)
      add_test(NAME collision.badflag.${name}
        COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:collision> "-DARGS=${args}"
          "-DEXPECT=${expect}" -P ${CMAKE_CURRENT_LIST_DIR}/common/tests/expect_usage_error.cmake)
    endfunction()
    mk_collision_badflag(trials "--trials|0" "^collision: --trials: expected an integer in \\[1, 10000000\\], got '0'$")
    mk_collision_badflag(pair "--pair|cubes" "^collision: --pair: expected one of ellipsoids[|]superquadrics[|]both, got 'cubes'$")
    mk_collision_badflag(rotations "--rotations|haar" "^collision: --rotations: expected one of paper[|]uniform, got 'haar'$")
    mk_collision_badflag(margin "--margin|2" "^collision: --margin: expected a number in \\[0, 1\\], got '2'$")
    mk_collision_badflag(seed "--seed|x" "^collision: --seed: expected an integer in \\[0, 2\\^64-1\\]")
    mk_collision_badflag(shard "--shard|2/2" "^collision: --shard: expected I/N with 1 <= N <= 1000000 and 0 <= I < N, got '2/2'$")
    mk_collision_badflag(unknown "--bogus|1" "^collision: --bogus: unknown option")
    mk_collision_badflag(missing "--trials" "^collision: --trials: missing value")
    mk_collision_badflag(forcevalue "--force=1" "^collision: --force: takes no value$")
    add_test(NAME collision.help COMMAND collision --help)
    set_tests_properties(collision.help PROPERTIES PASS_REGULAR_EXPRESSION "--pair ellipsoids[|]superquadrics[|]both")
    # A tiny run writes the documented columns, the right algorithms per
    # pair, and the sidecar keys tables.c reads.
    # With gnuplot, the figure's script draws the tiny run too.
    find_program(MKCOLLISION_GNUPLOT gnuplot)
    if(NOT MKCOLLISION_GNUPLOT)
      message(STATUS "gnuplot not found: collision.tiny does not draw plots/collision.gp")
      set(MKCOLLISION_GNUPLOT "")
    endif()
    add_test(NAME collision.tiny
      COMMAND ${CMAKE_COMMAND} -DMODE=tiny -DEXE=$<TARGET_FILE:collision>
        -DWORK=${CMAKE_CURRENT_BINARY_DIR}/collision_tiny "-DGNUPLOT=${MKCOLLISION_GNUPLOT}"
        -DPLOT=${PROJECT_SOURCE_DIR}/plots/collision.gp -P ${mk_collision_script})
    # Shards concatenate to the unsplit run, the timing column aside.
    add_test(NAME collision.shards
      COMMAND ${CMAKE_COMMAND} -DMODE=shards -DEXE=$<TARGET_FILE:collision>
        -DWORK=${CMAKE_CURRENT_BINARY_DIR}/collision_shards -P ${mk_collision_script})
    set_tests_properties(collision.tiny collision.shards PROPERTIES TIMEOUT 120)
  endif()
endif()

else() # ---- script mode -------------------------------------------------

# The lines of a CSV with the 4th field (seconds) emptied.
function(mk_collision_untimed path outvar)
  file(STRINGS ${path} lines)
  set(out "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^([^,]*,[^,]*,[^,]*,)[^,]*," "\\1," line "${line}")
    string(APPEND out "${line}\n")
  endforeach()
  set(${outvar} "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(MODE STREQUAL "tiny")
  execute_process(COMMAND ${EXE} --trials 2 --seed 7 --out ${WORK}/c.csv RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run failed (${rc}): ${err}")
  endif()
  file(STRINGS ${WORK}/c.csv lines)
  list(GET lines 0 head)
  if(NOT head STREQUAL "pair,trial,algorithm,seconds,collide,residual,iterations,success,referee_min_g,agrees")
    message(FATAL_ERROR "header is '${head}'")
  endif()
  # 2 trials x (6 ellipsoid algorithms + 5 superquadric ones) + the header
  list(LENGTH lines n)
  if(NOT n EQUAL 23)
    message(FATAL_ERROR "expected 23 lines, got ${n}")
  endif()
  foreach(alg "GJK" "ASC" "Implicit" "Common Normal" "MinkSum \\(Ray\\)" "MinkSum \\(Normal\\)")
    set(found 0)
    foreach(line IN LISTS lines)
      if(line MATCHES "^ellipsoids,0,${alg},[0-9.e-]+,[01],")
        set(found 1)
      endif()
    endforeach()
    if(NOT found)
      message(FATAL_ERROR "no ellipsoid row of trial 0 for ${alg}")
    endif()
  endforeach()
  foreach(line IN LISTS lines)
    if(line MATCHES "^superquadrics,[0-9]+,ASC,")
      message(FATAL_ERROR "ASC ran on superquadrics: ${line}")
    endif()
    if(line MATCHES "^[a-z]+,[0-9]+,(GJK|ASC),[^,]*,[01],[^,]")
      message(FATAL_ERROR "GJK/ASC row with a residual: ${line}")
    endif()
  endforeach()
  file(STRINGS ${WORK}/c.csv.meta rot REGEX "^rotation_draw: paper$")
  file(STRINGS ${WORK}/c.csv.meta ipopt REGEX "^ipopt_version: [0-9]")
  if(NOT rot OR NOT ipopt)
    message(FATAL_ERROR "sidecar lacks rotation_draw or ipopt_version")
  endif()
  # The figure: the script reads the rows alone and says how many trials
  # per pair kind it found.
  if(GNUPLOT)
    execute_process(COMMAND ${GNUPLOT} -e "results='${WORK}/c.csv'; outdir='${WORK}'" ${PLOT}
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/collision.png OR NOT EXISTS ${WORK}/collision.pdf)
      message(FATAL_ERROR "plots/collision.gp failed (${rc}): ${err}")
    endif()
    if(NOT "${out}${err}" MATCHES "2 trials per pair kind")
      message(FATAL_ERROR "plots/collision.gp did not count 2 trials: ${out}${err}")
    endif()
    if("${err}" MATCHES "[Ww]arning")
      message(FATAL_ERROR "plots/collision.gp warned: ${err}")
    endif()
  endif()
elseif(MODE STREQUAL "shards")
  set(args --trials 3 --seed 11)
  execute_process(COMMAND ${EXE} ${args} --out ${WORK}/all.csv RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "unsplit run failed (${rc}): ${err}")
  endif()
  mk_collision_untimed(${WORK}/all.csv whole)
  set(joined "")
  foreach(i 0 1)
    execute_process(COMMAND ${EXE} ${args} --shard ${i}/2 --out ${WORK}/p${i}.csv RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "shard ${i}/2 failed (${rc}): ${err}")
    endif()
    mk_collision_untimed(${WORK}/p${i}.csv text)
    if(NOT i EQUAL 0)
      string(FIND "${text}" "\n" eol)
      math(EXPR start "${eol} + 1")
      string(SUBSTRING "${text}" ${start} -1 text)
    endif()
    string(APPEND joined "${text}")
  endforeach()
  if(NOT joined STREQUAL whole)
    file(WRITE ${WORK}/joined.csv "${joined}")
    message(FATAL_ERROR "concatenated shards differ from the unsplit run (seconds aside): see ${WORK}")
  endif()
else()
  message(FATAL_ERROR "collision.cmake: unknown MODE '${MODE}'")
endif()
file(REMOVE_RECURSE ${WORK})

endif()
