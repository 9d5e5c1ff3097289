# timing.cmake - the running-time driver `timing` (paper Sec. 6.3), the
# paper-vs-reproduction table generator `tables`, and their tests.
#
# This file has two uses. Included from experiments/CMakeLists.txt it adds
# the targets and registers the tests. Run as a script
# (cmake -DMODE=... -P timing.cmake) it is the body of those tests that need
# more than one command: MODE=tiny, shards, cap or tables (see the end).

if(NOT CMAKE_SCRIPT_MODE_FILE)

if(NOT TARGET mink_baselines)
  message(STATUS "timing: the baselines are not built (MINK_BUILD_BASELINES=OFF); no timing driver")
else()
  # The versions of the libraries the timed methods run on, for the
  # results' metadata. CGAL is header-only: its version is read from its
  # header here, so that the driver need not include CGAL.
  find_path(MK_TIMING_CGAL_INCLUDE_DIR CGAL/version.h)
  set(mk_timing_cgal "unknown")
  if(MK_TIMING_CGAL_INCLUDE_DIR)
    file(STRINGS ${MK_TIMING_CGAL_INCLUDE_DIR}/CGAL/version.h mk_timing_cgal_line
      REGEX "^#define CGAL_VERSION [0-9]")
    string(REGEX REPLACE "^#define CGAL_VERSION ([0-9.]+).*" "\\1" mk_timing_cgal "${mk_timing_cgal_line}")
  endif()
  find_path(MK_TIMING_QHULL_INCLUDE_DIR libqhull_r/libqhull_r.h REQUIRED)
  find_library(MK_TIMING_QHULL_LIBRARY qhull_r REQUIRED)
  find_library(MK_TIMING_GMP_LIBRARY gmp REQUIRED)
  find_library(MK_TIMING_MPFR_LIBRARY mpfr REQUIRED)

  add_executable(timing ${CMAKE_CURRENT_LIST_DIR}/timing.c)
  target_include_directories(timing PRIVATE ${MK_TIMING_QHULL_INCLUDE_DIR})
  target_compile_definitions(timing PRIVATE MK_TIMING_CGAL_VERSION="${mk_timing_cgal}")
  target_link_libraries(timing PRIVATE mink_baselines mink_exp
    ${MK_TIMING_QHULL_LIBRARY} ${MK_TIMING_MPFR_LIBRARY} ${MK_TIMING_GMP_LIBRARY} m)
  target_compile_options(timing PRIVATE ${MINK_C_WARNINGS})
endif()

# tables: reads results/*.csv (and their sidecars) only.
add_executable(tables ${CMAKE_CURRENT_LIST_DIR}/tables.c)
target_link_libraries(tables PRIVATE mink_exp m)
target_compile_options(tables PRIVATE ${MINK_C_WARNINGS})

if(MINK_BUILD_TESTS)
  set(mk_timing_script ${CMAKE_CURRENT_LIST_DIR}/timing.cmake)
  if(TARGET timing)
    # Bad flags: a one-line error naming the flag and its range, exit 2.
    # Arguments are separated by "|".
    function(mk_timing_badflag name args expect)
      add_test(NAME timing.badflag.${name}
        COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:timing> "-DARGS=${args}"
          "-DEXPECT=${expect}" -P ${CMAKE_CURRENT_LIST_DIR}/common/tests/expect_usage_error.cmake)
    endfunction()
    mk_timing_badflag(trials "--trials|0" "^timing: --trials: expected an integer in \\[1, 1000000\\], got '0'$")
    mk_timing_badflag(dims "--dims|4" "^timing: --dims: expected one of 2[|]3[|]both, got '4'$")
    mk_timing_badflag(cases "--cases|EE,XY" "^timing: --cases: expected a comma-separated list of EE, ES, SQ \\(or all\\), got 'EE,XY'$")
    mk_timing_badflag(methods "--methods|closed-gradient,nope" "^timing: --methods: expected a comma-separated list of closed-normal, .*hull-qhull.* \\(or all\\), got 'closed-gradient,nope'$")
    mk_timing_badflag(levels_dim "--levels|4d=5" "^timing: --levels: expected 2d=LIST or 3d=LIST")
    mk_timing_badflag(levels_range "--levels|3d=5:5:3005" "^timing: --levels: 3d level 3005 is outside \\[3, 3000\\] in '3d=5:5:3005'$")
    mk_timing_badflag(levels_low "--levels|2d=2,20" "^timing: --levels: 2d level 2 is outside \\[3, 100000\\] in '2d=2,20'$")
    mk_timing_badflag(levels_form "--levels|2d=20:500" "^timing: --levels: expected 2d=LIST with LIST comma-separated integers or START:STEP:STOP ranges")
    mk_timing_badflag(levels_step "--levels|2d=20:0:500" "^timing: --levels: expected 2d=LIST")
    mk_timing_badflag(levels_empty "--levels|3d=" "^timing: --levels: expected 3d=LIST")
    mk_timing_badflag(rotations "--rotations|haar" "^timing: --rotations: expected one of paper[|]uniform, got 'haar'$")
    mk_timing_badflag(budget "--budget|-1" "^timing: --budget: expected a number of seconds in \\[0, 1e\\+06\\], got '-1'$")
    mk_timing_badflag(budget_text "--budget|2s" "^timing: --budget: expected a number of seconds in \\[0, 1e\\+06\\], got '2s'$")
    mk_timing_badflag(min_trials "--min-trials|0" "^timing: --min-trials: expected an integer in \\[1, 1000000\\], got '0'$")
    mk_timing_badflag(seed "--seed|x" "^timing: --seed: expected an integer in \\[0, 2\\^64-1\\]")
    mk_timing_badflag(shard "--shard|3/3" "^timing: --shard: expected I/N with 1 <= N <= 1000000 and 0 <= I < N, got '3/3'$")
    mk_timing_badflag(out "--out=" "^timing: --out: expected a file path, got ''$")
    mk_timing_badflag(unknown "--bogus|1" "^timing: --bogus: unknown option")
    mk_timing_badflag(missing "--trials" "^timing: --trials: missing value")
    mk_timing_badflag(forcevalue "--force=1" "^timing: --force: takes no value$")

    # A tiny run: the rows expected from the arguments, the skips recorded,
    # the refusal to overwrite without --force.
    add_test(NAME timing.tiny
      COMMAND ${CMAKE_COMMAND} -DMODE=tiny -DEXE=$<TARGET_FILE:timing>
        -DWORK=${CMAKE_CURRENT_BINARY_DIR}/timing_tiny -P ${mk_timing_script})
    # Shards of a run concatenate to the unsplit run, row for row, once the
    # two measured columns are set aside.
    add_test(NAME timing.shards
      COMMAND ${CMAKE_COMMAND} -DMODE=shards -DEXE=$<TARGET_FILE:timing>
        -DWORK=${CMAKE_CURRENT_BINARY_DIR}/timing_shards -P ${mk_timing_script})
    # The trial cap: with no budget every cell runs --min-trials trials and
    # says so in every row.
    add_test(NAME timing.cap
      COMMAND ${CMAKE_COMMAND} -DMODE=cap -DEXE=$<TARGET_FILE:timing>
        -DWORK=${CMAKE_CURRENT_BINARY_DIR}/timing_cap -P ${mk_timing_script})
    set_tests_properties(timing.tiny timing.shards timing.cap PROPERTIES TIMEOUT 120)
  endif()
  # The tables from small hand-made result files: every published number,
  # the "not reproduced yet" rows, the ratios.
  add_test(NAME tables.fixture
    COMMAND ${CMAKE_COMMAND} -DMODE=tables -DEXE=$<TARGET_FILE:tables>
      -DWORK=${CMAKE_CURRENT_BINARY_DIR}/tables_fixture -P ${mk_timing_script})
  set_tests_properties(tables.fixture PROPERTIES TIMEOUT 60)
endif()

return()
endif()

# ---- script mode: the test bodies --------------------------------------------

function(mk_fail)
  string(JOIN " " text ${ARGN})
  message(FATAL_ERROR "${text}")
endfunction()

# Run EXE with the given arguments; fail unless it exits with 0.
function(mk_run)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    mk_fail("${EXE} ${ARGN} exited with ${rc}: ${err}")
  endif()
endfunction()

# Read a CSV (no quoted fields: the timing driver writes none) into
# <prefix>_header (list of names) and <prefix>_rows (list of lines, each
# with commas kept).
function(mk_read_csv path prefix)
  file(STRINGS ${path} lines)
  list(POP_FRONT lines header)
  string(REPLACE "," ";" header "${header}")
  set(${prefix}_header "${header}" PARENT_SCOPE)
  set(${prefix}_rows "${lines}" PARENT_SCOPE)
endfunction()

# The value of column `name` in a row (a line of commas).
function(mk_field header row name out)
  list(FIND header ${name} i)
  if(i LESS 0)
    mk_fail("no column ${name} in header ${header}")
  endif()
  string(REPLACE "," ";" fields "${row}")
  list(GET fields ${i} v)
  set(${out} "${v}" PARENT_SCOPE)
endfunction()

# Count the rows of a CSV whose columns have the given values:
# mk_count(<header> <rows> <out> col1 val1 col2 val2 ...).
function(mk_count header rows out)
  set(n 0)
  foreach(row IN LISTS rows)
    set(match 1)
    set(args ${ARGN})
    while(args)
      list(POP_FRONT args col val)
      mk_field("${header}" "${row}" ${col} v)
      if(NOT v STREQUAL val)
        set(match 0)
        break()
      endif()
    endwhile()
    if(match)
      math(EXPR n "${n} + 1")
    endif()
  endforeach()
  set(${out} ${n} PARENT_SCOPE)
endfunction()

function(mk_expect_eq what got want)
  if(NOT "${got}" STREQUAL "${want}")
    mk_fail("${what}: got '${got}', expected '${want}'")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

if(MODE STREQUAL "tiny")
  # 2D levels 5 and 8, 3D levels 3 and 4, 3 trials, cases EE and SQ. Rows
  # expected, from the registry (8 methods; the geometric one needs body 2 an
  # ellipse, edge sorting runs in 2D only):
  #   2D EE 8 methods x 2 levels x 3 = 48, 2D SQ 7 x 2 x 3 = 42,
  #   3D EE 7 x 2 x 3 = 42,                3D SQ 6 x 2 x 3 = 36;  168 in all.
  set(args --trials 3 --seed 7 --cases EE,SQ --levels 2d=5,8 --levels 3d=3:1:4 --budget 1e6)
  mk_run(${args} --out ${WORK}/t.csv)
  mk_read_csv(${WORK}/t.csv t)
  mk_expect_eq("header" "${t_header}"
    "dim;case;method;level;points_per_body;trial;status;seconds;points_out;trials_planned;trials_run;warmup_seconds")
  list(LENGTH t_rows n)
  mk_expect_eq("rows" ${n} 168)
  mk_count("${t_header}" "${t_rows}" n status ok)
  mk_expect_eq("rows with status ok" ${n} 168)
  mk_count("${t_header}" "${t_rows}" n trials_run 3)
  mk_expect_eq("rows whose cell ran all 3 trials" ${n} 168)
  mk_count("${t_header}" "${t_rows}" n dim 2 case SQ method geometric)
  mk_expect_eq("2D SQ geometric rows" ${n} 0)
  mk_count("${t_header}" "${t_rows}" n dim 3 method edge-sort)
  mk_expect_eq("3D edge-sort rows" ${n} 0)
  # A closed form gives one point per parameter of body 1: N in 2D, n*n in 3D.
  mk_count("${t_header}" "${t_rows}" n dim 2 method closed-gradient level 8 points_out 8)
  mk_expect_eq("2D closed-gradient rows at N = 8 with 8 points" ${n} 6)
  mk_count("${t_header}" "${t_rows}" n dim 3 method closed-normal level 4 points_per_body 16 points_out 16)
  mk_expect_eq("3D closed-normal rows at n = 4 with 16 points" ${n} 6)
  # Every time is a positive number of seconds below a minute.
  foreach(row IN LISTS t_rows)
    mk_field("${t_header}" "${row}" seconds s)
    if(NOT s MATCHES "^[0-9.e-]+$" OR s STREQUAL "0" OR s MATCHES "^[0-9.]*e\\+")
      mk_fail("row '${row}': seconds '${s}' is not a small positive number")
    endif()
  endforeach()
  # The sidecar says what was skipped and how the clock was used.
  file(READ ${WORK}/t.csv.meta meta)
  foreach(want "experiment: timing" "rows: 168" "rotation_draw: paper" "threads: 1"
      "2D SQ geometric: 6 of 6 pairs not accepted" "3D EE edge-sort: 6 of 6 pairs not accepted"
      "clock: CLOCK_MONOTONIC" "capped_cells: 0" "failed_calls: 0" "levels_2d: 5,8" "levels_3d: 3,4")
    string(FIND "${meta}" "${want}" at)
    if(at LESS 0)
      mk_fail("the sidecar lacks '${want}':\n${meta}")
    endif()
  endforeach()
  # An existing result is kept unless --force.
  execute_process(COMMAND ${EXE} ${args} --out ${WORK}/t.csv RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "exists; pass --force")
    mk_fail("a second run without --force: exit ${rc}, '${err}'")
  endif()

elseif(MODE STREQUAL "shards")
  set(args --trials 4 --seed 99 --cases all --levels 2d=6:3:12 --levels 3d=3,5 --budget 1e6)
  mk_run(${args} --out ${WORK}/all.csv)
  # The measured columns differ from run to run; everything else must not.
  function(mk_strip_times path out)
    mk_read_csv(${path} s)
    list(FIND s_header seconds is)
    list(FIND s_header warmup_seconds iw)
    set(kept "")
    foreach(row IN LISTS s_rows)
      string(REPLACE "," ";" f "${row}")
      list(REMOVE_AT f ${iw} ${is})
      string(JOIN "," line ${f})
      list(APPEND kept "${line}")
    endforeach()
    set(${out} "${kept}" PARENT_SCOPE)
  endfunction()
  mk_strip_times(${WORK}/all.csv whole)
  set(joined "")
  foreach(i RANGE 0 2)
    mk_run(${args} --shard ${i}/3 --out ${WORK}/part${i}.csv)
    mk_strip_times(${WORK}/part${i}.csv part)
    list(APPEND joined ${part})
    file(STRINGS ${WORK}/part${i}.csv.meta shardline REGEX "^shard: ")
    mk_expect_eq("shard line of part ${i}" "${shardline}" "shard: ${i}/3")
  endforeach()
  list(LENGTH whole nw)
  list(LENGTH joined nj)
  mk_expect_eq("rows of the shards together" ${nj} ${nw})
  if(NOT joined STREQUAL whole)
    string(REPLACE ";" "\n" a "${whole}")
    string(REPLACE ";" "\n" b "${joined}")
    file(WRITE ${WORK}/whole.txt "${a}\n")
    file(WRITE ${WORK}/joined.txt "${b}\n")
    mk_fail("concatenated shards differ from the unsplit run: compare ${WORK}/joined.txt with ${WORK}/whole.txt")
  endif()
  file(GLOB leftovers ${WORK}/*.tmp.*)
  if(leftovers)
    mk_fail("temporary files left: ${leftovers}")
  endif()

elseif(MODE STREQUAL "cap")
  # No budget: every cell runs --min-trials (2) of its 5 trials. 2D SQ at
  # two levels: 7 methods x 2 levels x 2 trials = 28 rows, trials 0 and 1.
  mk_run(--trials 5 --min-trials 2 --budget 0 --dims 2 --cases SQ --levels 2d=10,20 --out ${WORK}/c.csv)
  mk_read_csv(${WORK}/c.csv c)
  list(LENGTH c_rows n)
  mk_expect_eq("rows" ${n} 28)
  mk_count("${c_header}" "${c_rows}" n trials_planned 5 trials_run 2)
  mk_expect_eq("rows saying 2 of 5 trials ran" ${n} 28)
  mk_count("${c_header}" "${c_rows}" n trial 1)
  mk_expect_eq("rows of trial 1" ${n} 14)
  file(STRINGS ${WORK}/c.csv.meta capped REGEX "^capped_cells: ")
  mk_expect_eq("capped cells in the sidecar" "${capped}" "capped_cells: 14")

elseif(MODE STREQUAL "tables")
  # Hand-made result files whose means are worked out here:
  #  validation, 2D paper form: e_implicit rows 4e-16 and 8e-16 (mean 6e-16,
  #  ratio 6 / 5.9194 = 1.0136 -> "1.01"); e_gradient rows 1e-6 and 3e-6
  #  (mean 2e-6, ratio 2 / 0.61839 = 3.234 -> "3.23").
  #  timing, 2D SQ at N = 10, 20, 40, 80, 160: closed-gradient 1e-6 N s
  #  (slope 1), edge-sort 0.5e-6 N s (faster at all 5 levels), hull-qhull
  #  1e-8 N^2 s (slope 2; at N = 160 it takes 2.56e-4 s against 1.6e-4 s,
  #  ratio 1.6 < 10, so that statement must read "disagrees"). One trial
  #  per level: the medians the statements use are these times.
  #  No fitting, C-obstacle or collision results: their 9 + 12 + 11 published
  #  numbers are "not reproduced yet"; validation has 4 and the running-time
  #  text 6 statements: 42 in all, 10 with a counterpart.
  file(WRITE ${WORK}/validation.csv
"dim,trial,form,e_implicit_mean,e_gradient_mean,e_support_mean,nonfinite_count
2,0,paper,4e-16,1e-6,1e-16,0
2,1,paper,8e-16,3e-6,3e-16,0
2,0,gradient,1e-16,1e-6,1e-16,0
2,1,gradient,1e-16,1e-6,1e-16,0
3,0,paper,2e-9,1e-6,1e-15,2
3,0,gradient,1e-15,1e-6,1e-15,0
")
  file(WRITE ${WORK}/validation.csv.meta "experiment: validation\nseed: 5\ntrials: 2\nrotation_draw: uniform\n")
  set(rows "dim,case,method,level,points_per_body,trial,status,seconds,points_out,trials_planned,trials_run,warmup_seconds\n")
  foreach(n 10 20 40 80 160)
    math(EXPR half "${n} * 5")
    math(EXPR square "${n} * ${n}")
    string(APPEND rows "2,SQ,closed-gradient,${n},${n},0,ok,${n}e-6,${n},1,1,0\n")
    string(APPEND rows "2,SQ,edge-sort,${n},${n},0,ok,${half}e-7,${n},1,1,0\n")
    string(APPEND rows "2,SQ,hull-qhull,${n},${n},0,ok,${square}e-8,${n},1,1,0\n")
  endforeach()
  file(WRITE ${WORK}/timing.csv "${rows}")
  file(WRITE ${WORK}/timing.csv.meta "experiment: timing\nseed: 1\ntrials: 1\nrotation_draw: paper\n")
  execute_process(COMMAND ${EXE} --results ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    mk_fail("tables exited with ${rc}: ${err}")
  endif()
  if(NOT out MATCHES "42 published figures and statements, 10 reproduced, 32 not reproduced yet")
    mk_fail("unexpected tally: ${out}")
  endif()
  file(READ ${WORK}/tables.md md)
  foreach(want
      "| 2D | e_implicit | 5.9194e-16 | 6.0000e-16 | 1.01 |"
      "| 2D | e_gradient | 6.1839e-7 | 2.0000e-06 | 3.23 |"
      "Rotation draw (3D): **uniform**"
      "| case 1: superquadric fitted to a random polyhedron, e_volume | 0.2095 | **NOT REPRODUCED YET** |"
      "| closed form (proposed) is linear in N | 2D | SQ | slope of closed-gradient, 20–160 points | 1.00 |"
      "| edge sorting is faster than the closed form for two superellipses | 2D | SQ | levels where edge-sort is faster than closed-gradient | 5 of 5 |"
      "| convex hull grows much faster | 2D | SQ | slopes of hull-qhull and closed-gradient; time ratio at level 160 | 2.00 vs 1.00; 1.6 | slopes differ by ≥ 0.5 and ratio ≥ 10 | **disagrees** |"
      "| 3D | 1000 | 100 | 3600 | 1907.85 | **NOT REPRODUCED YET** |"
      "| MinkSum (Normal) | 3.5 | **NOT REPRODUCED YET** |")
    string(FIND "${md}" "${want}" at)
    if(at LESS 0)
      mk_fail("tables.md lacks '${want}':\n${md}")
    endif()
  endforeach()
  file(READ ${WORK}/tables.tex tex)
  foreach(want "\\begin{document}" "\\end{document}" "\\textbf{NOT REPRODUCED YET}" "5.9194e-16")
    string(FIND "${tex}" "${want}" at)
    if(at LESS 0)
      mk_fail("tables.tex lacks '${want}'")
    endif()
  endforeach()

else()
  mk_fail("unknown MODE '${MODE}'")
endif()

file(REMOVE_RECURSE ${WORK})
