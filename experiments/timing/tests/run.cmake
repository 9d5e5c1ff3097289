# run.cmake - the bodies of the timing driver's tests that need more than
# one command: cmake -DMODE=tiny|cap -DEXE=... -DMINK=... -DWORK=... -P run.cmake

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

# The registry's methods per dimension, from `mink methods` (MINK, the mink
# command): <prefix>_2 and <prefix>_3, lists of names. The tests below
# derive every row count from them, so that a new method changes no test.
function(mk_registry prefix)
  execute_process(COMMAND ${MINK} methods RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    mk_fail("${MINK} methods exited with ${rc}")
  endif()
  # Square brackets (the n ranges) would keep CMake from splitting the list.
  string(REPLACE "[" "(" out "${out}")
  string(REPLACE "]" ")" out "${out}")
  string(REPLACE "\n" ";" lines "${out}")
  set(two "")
  set(three "")
  foreach(line IN LISTS lines)
    # (each MATCHES resets CMAKE_MATCH_<n>: the groups are kept first)
    if(line MATCHES "^([a-z0-9][a-z0-9._-]*) +([23D,]+) ")
      set(mname ${CMAKE_MATCH_1})
      set(mdims ${CMAKE_MATCH_2})
      if(mname STREQUAL "name")
        continue()
      endif()
      if(mdims MATCHES "2D")
        list(APPEND two ${mname})
      endif()
      if(mdims MATCHES "3D")
        list(APPEND three ${mname})
      endif()
    endif()
  endforeach()
  set(${prefix}_2 "${two}" PARENT_SCOPE)
  set(${prefix}_3 "${three}" PARENT_SCOPE)
endfunction()

# The pairs the sidecar says were not accepted ("2D SQ geometric: 6 of 6
# pairs not accepted"), summed for one dimension (2 or 3) and case over the
# methods that run in that dimension (the list `methods`; the sidecar also
# names the methods that do not run there at all).
function(mk_refused meta dim case methods out)
  set(n 0)
  foreach(m IN LISTS methods)
    if(meta MATCHES "${dim}D ${case} ${m}: ([0-9]+) of [0-9]+ pairs not accepted")
      math(EXPR n "${n} + ${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${out} ${n} PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "tiny")
  # 2D levels 5 and 8, 3D levels 3 and 4, 3 trials, cases EE and SQ: each
  # method of a dimension runs 2 levels x 3 trials = 6 pairs per case, less
  # the pairs it does not accept, which the sidecar lists (the geometric
  # method needs body 2 an ellipse; a 2D-only method has no 3D rows).
  set(args --trials 3 --seed 7 --cases EE,SQ --levels 2d=5,8 --levels 3d=3:1:4 --budget 1e6)
  mk_run(${args} --out ${WORK}/t.csv)
  mk_read_csv(${WORK}/t.csv t)
  file(READ ${WORK}/t.csv.meta meta)
  mk_registry(reg)
  set(want 0)
  foreach(dim 2 3)
    list(LENGTH reg_${dim} nm)
    foreach(case EE SQ)
      mk_refused("${meta}" ${dim} ${case} "${reg_${dim}}" refused)
      math(EXPR want "${want} + ${nm} * 6 - ${refused}")
      foreach(m IN LISTS reg_${dim})
        mk_count("${t_header}" "${t_rows}" k dim ${dim} case ${case} method ${m})
        string(FIND "${meta}" "${dim}D ${case} ${m}: 6 of 6 pairs not accepted" skipped)
        if(k EQUAL 0 AND skipped LESS 0)
          mk_fail("no ${dim}D ${case} rows of method ${m}, and the sidecar does not say it refused them")
        endif()
      endforeach()
    endforeach()
  endforeach()
  mk_expect_eq("header" "${t_header}"
    "dim;case;method;level;points_per_body;trial;status;seconds;points_out;trials_planned;trials_run;warmup_seconds")
  list(LENGTH t_rows n)
  mk_expect_eq("rows" ${n} ${want})
  mk_count("${t_header}" "${t_rows}" n status ok)
  mk_expect_eq("rows with status ok" ${n} ${want})
  mk_count("${t_header}" "${t_rows}" n trials_run 3)
  mk_expect_eq("rows whose cell ran all 3 trials" ${n} ${want})
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
  foreach(want "experiment: timing" "rows: ${want}" "rotation_draw: paper" "threads: 1"
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
  # two levels: the 2D methods that take SQ pairs (all but those the sidecar
  # lists as not accepted) x 2 levels x 2 trials, trials 0 and 1.
  mk_run(--trials 5 --min-trials 2 --budget 0 --dim 2 --cases SQ --levels 2d=10,20 --out ${WORK}/c.csv)
  mk_read_csv(${WORK}/c.csv c)
  file(READ ${WORK}/c.csv.meta meta)
  mk_registry(reg)
  list(LENGTH reg_2 nm)
  mk_refused("${meta}" 2 SQ "${reg_2}" refused)
  math(EXPR cells "(${nm} * 10 - ${refused}) / 5")
  math(EXPR want "${cells} * 2")
  list(LENGTH c_rows n)
  mk_expect_eq("rows" ${n} ${want})
  mk_count("${c_header}" "${c_rows}" n trials_planned 5 trials_run 2)
  mk_expect_eq("rows saying 2 of 5 trials ran" ${n} ${want})
  mk_count("${c_header}" "${c_rows}" n trial 1)
  mk_expect_eq("rows of trial 1" ${n} ${cells})
  file(STRINGS ${WORK}/c.csv.meta capped REGEX "^capped_cells: ")
  mk_expect_eq("capped cells in the sidecar" "${capped}" "capped_cells: ${cells}")

else()
  mk_fail("unknown MODE '${MODE}'")
endif()

file(REMOVE_RECURSE ${WORK})
