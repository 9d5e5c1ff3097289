# run.cmake - the bodies of the timing driver's tests that need more than
# one command: cmake -DMODE=tiny|cap -DEXE=... -DWORK=... -P run.cmake

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
  # expected, from the registry (10 methods; the geometric one needs body 2
  # an ellipse, edge sorting runs in 2D only):
  #   2D EE 10 methods x 2 levels x 3 = 60, 2D SQ 9 x 2 x 3 = 54,
  #   3D EE 9 x 2 x 3 = 54,                 3D SQ 8 x 2 x 3 = 48;  216 in all.
  set(args --trials 3 --seed 7 --cases EE,SQ --levels 2d=5,8 --levels 3d=3:1:4 --budget 1e6)
  mk_run(${args} --out ${WORK}/t.csv)
  mk_read_csv(${WORK}/t.csv t)
  mk_expect_eq("header" "${t_header}"
    "dim;case;method;level;points_per_body;trial;status;seconds;points_out;trials_planned;trials_run;warmup_seconds")
  list(LENGTH t_rows n)
  mk_expect_eq("rows" ${n} 216)
  mk_count("${t_header}" "${t_rows}" n status ok)
  mk_expect_eq("rows with status ok" ${n} 216)
  mk_count("${t_header}" "${t_rows}" n trials_run 3)
  mk_expect_eq("rows whose cell ran all 3 trials" ${n} 216)
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
  foreach(want "experiment: timing" "rows: 216" "rotation_draw: paper" "threads: 1"
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

elseif(MODE STREQUAL "cap")
  # No budget: every cell runs --min-trials (2) of its 5 trials. 2D SQ at
  # two levels: 9 methods x 2 levels x 2 trials = 36 rows, trials 0 and 1.
  mk_run(--trials 5 --min-trials 2 --budget 0 --dim 2 --cases SQ --levels 2d=10,20 --out ${WORK}/c.csv)
  mk_read_csv(${WORK}/c.csv c)
  list(LENGTH c_rows n)
  mk_expect_eq("rows" ${n} 36)
  mk_count("${c_header}" "${c_rows}" n trials_planned 5 trials_run 2)
  mk_expect_eq("rows saying 2 of 5 trials ran" ${n} 36)
  mk_count("${c_header}" "${c_rows}" n trial 1)
  mk_expect_eq("rows of trial 1" ${n} 18)
  file(STRINGS ${WORK}/c.csv.meta capped REGEX "^capped_cells: ")
  mk_expect_eq("capped cells in the sidecar" "${capped}" "capped_cells: 18")

else()
  mk_fail("unknown MODE '${MODE}'")
endif()

file(REMOVE_RECURSE ${WORK})
