# external.cmake - external methods (mink/external.h) through `mink sum`,
# `mink verify`, the timing and the tradeoff drivers, with small programs in
# tests/external: a correct one (docs/compare/support.py, exact support
# points, judged by `mink score`) and a crashing, a hanging, a garbage and a
# refusing one, whose failures must be their rows' status, never the run's.
# cmake -DMINK=<mink> -DTIMING=<timing> -DTRADEOFF=<tradeoff> -DSRC=<top>
#       -DWORK=<scratch> -P external.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ext ${SRC}/experiments/mink/tests/external)
set(support "exec:support=python3 ${SRC}/docs/compare/support.py")
set(B1 "superellipse a=3 b=2 eps=0.5 rot=0.3")
set(B2 "ellipse a=1 b=0.5 at=4,4")
set(Q1 "superquadric a=3 b=2 c=1 eps1=0.4 eps2=1.3")
set(Q2 "ellipsoid a=1 b=0.5 c=2")

function(run rc_want)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL rc_want)
    message(FATAL_ERROR "${ARGN}\nexited with ${rc}, not ${rc_want}: ${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# The correct method: exact support points, so every point is on the true
# boundary to rounding by the independent measure; one point per normal.
foreach(d 2 3)
  if(d EQUAL 2)
    set(b1 "${B1}")
    set(b2 "${B2}")
    set(count 16)
  else()
    set(b1 "${Q1}")
    set(b2 "${Q2}")
    set(count 36)
  endif()
  foreach(set contact plus)
    set(pts ${WORK}/support${d}${set}.csv)
    run(0 ${MINK} sum --dim ${d} --set ${set} --method ${support} --n 6 --body1 ${b1} --body2 ${b2} --out ${pts})
    if(d EQUAL 2)
      run(0 ${MINK} sum --dim ${d} --set ${set} --method ${support} --n 16 --body1 ${b1} --body2 ${b2} --out ${pts})
    endif()
    file(STRINGS ${pts} lines)
    list(LENGTH lines n)
    math(EXPR n "${n} - 1")
    if(NOT n EQUAL count)
      message(FATAL_ERROR "${d}D ${set}: ${n} points, not ${count}")
    endif()
    run(0 ${MINK} score --dim ${d} --set ${set} --body1 ${b1} --body2 ${b2} --points ${pts} --csv)
    string(REGEX MATCH "\n[^\n]+" row "${out}")
    string(REPLACE "," ";" row "${row}")
    list(GET row 10 off_rel)
    if(NOT off_rel MATCHES "e-1[4-9]$|e-[2-9][0-9]$|^0$")
      message(FATAL_ERROR "${d}D ${set}: support.py's points lie ${off_rel} of the size off the boundary")
    endif()
    message(STATUS "${d}D ${set}: support.py's ${n} points within ${off_rel} of the size of the boundary")
  endforeach()
endforeach()

# mink verify takes it: unordered points, judged by the error measure against
# --tol (an external method states no accuracy, so --tol is required); the
# exact support points pass at 1e-13, and fail with one point far off.
run(2 ${MINK} verify --dim 2 --method ${support} --body1 ${B1} --body2 ${B2} --points ${WORK}/support2contact.csv)
if(NOT err MATCHES "declares its points unordered and states no accuracy: give --tol")
  message(FATAL_ERROR "verify: ${err}")
endif()
run(0 ${MINK} verify --dim 2 --method ${support} --body1 ${B1} --body2 ${B2} --points ${WORK}/support2contact.csv
  --tol 1e-13)
if(NOT out MATCHES "unordered: judged by the error measure\nPASS: largest distance off the boundary [0-9.e-]+ of the size")
  message(FATAL_ERROR "verify --tol: ${out}")
endif()
file(READ ${WORK}/support2contact.csv vtext)
file(WRITE ${WORK}/support2contact_off.csv "${vtext}1000,1000\n")
run(1 ${MINK} verify --dim 2 --method ${support} --body1 ${B1} --body2 ${B2} --points ${WORK}/support2contact_off.csv
  --tol 1e-13)
if(NOT out MATCHES "\nFAIL: largest distance off the boundary")
  message(FATAL_ERROR "verify --tol, a point off the boundary: ${out}")
endif()

# Failures: exit 1 from mink sum, with the reason.
set(ENV{MINK_EXEC_TIMEOUT} 1)
set(ENV{MINK_EXEC_STARTUP} 3)
foreach(case "crash;(died of signal 11|exited with status 139)" "hang;no answer within the time limit"
    "garbage;point 1: expected 2 numbers, got 'banana'" "refuse;this method takes no such pair")
  list(GET case 0 prog)
  list(GET case 1 want)
  run(1 ${MINK} sum --dim 2 --method "exec:sh ${ext}/${prog}.sh" --n 8 --body1 ${B1} --body2 ${B2})
  if(NOT err MATCHES "method exec-${prog} failed: .*${want}")
    message(FATAL_ERROR "${prog}: '${err}' does not say '${want}'")
  endif()
endforeach()

# The timing driver: the crashing and the hanging method's rows say so, the
# run goes on.
run(0 ${TIMING} --trials 2 --seed 3 --cases EE --dim 2 --levels 2d=5,8 --budget 1e6
  --methods "closed-normal,exec:crash=sh ${ext}/crash.sh,${support}" --out ${WORK}/timing.csv)
file(STRINGS ${WORK}/timing.csv rows)
run(0 ${TIMING} --trials 1 --seed 3 --cases EE --dim 2 --levels 2d=5 --budget 1e6
  --methods "closed-normal,exec:hang=sh ${ext}/hang.sh" --out ${WORK}/timing-hang.csv)
file(STRINGS ${WORK}/timing-hang.csv hang_rows)
list(APPEND rows ${hang_rows})
foreach(want "2,EE,crash,5,5,0,crashed," "2,EE,crash,8,8,1,crashed," "2,EE,support,8,8,1,ok,"
    "2,EE,closed-normal,8,8,1,ok," "2,EE,hang,5,5,0,timeout,")
  string(FIND "${rows}" "${want}" at)
  if(at LESS 0)
    message(FATAL_ERROR "timing: no row '${want}' in\n${rows}")
  endif()
endforeach()

# The tradeoff driver: a garbage method fails in its rows.
run(0 ${TRADEOFF} --trials 1 --seed 3 --levels 2d=8,16 --levels 3d=3 --budget 0 --repeats 1
  --methods "closed-normal,exec:garbage=sh ${ext}/garbage.sh,${support}"
  --out ${WORK}/tradeoff.csv)
file(STRINGS ${WORK}/tradeoff.csv rows)
foreach(want "^2,EE,garbage,contact,8,0,0,nan,nan,nan,nan,0,.*,garbage$" "^3,SQ,garbage,contact,3,0,0,nan,.*,garbage$"
    "^2,SQ,support,contact,16,0,16,[0-9.e-]+,[0-9.e-]+,.*,ok$" "^3,ES,support,contact,3,0,9,.*,ok$")
  set(found 0)
  foreach(row IN LISTS rows)
    if(row MATCHES "${want}")
      set(found 1)
    endif()
  endforeach()
  if(NOT found)
    message(FATAL_ERROR "tradeoff: no row matching '${want}'")
  endif()
endforeach()

# A methods file (--methods @FILE): comments and blank lines skipped, every
# NAME=COMMAND line a method in the run's rows; a bad line named with its
# file, line and field, exit 2.
file(WRITE ${WORK}/methods.txt "# two external methods\n\n  support=python3 ${SRC}/docs/compare/support.py\n"
  "crash = sh ${ext}/crash.sh\n")
run(0 ${TIMING} --trials 1 --seed 3 --cases EE --dim 2 --levels 2d=8 --budget 1e6
  --methods "closed-normal,@${WORK}/methods.txt" --out ${WORK}/timing-file.csv)
file(STRINGS ${WORK}/timing-file.csv rows)
foreach(want "2,EE,support,8,8,0,ok," "2,EE,crash,8,8,0,crashed," "2,EE,closed-normal,8,8,0,ok,")
  string(FIND "${rows}" "${want}" at)
  if(at LESS 0)
    message(FATAL_ERROR "timing with a methods file: no row '${want}' in\n${rows}")
  endif()
endforeach()
foreach(case "bad_name|ok=sh a.sh\n\n#c\nmy method=sh b.sh\n|methods-bad_name.txt line 4: NAME .my method.: must be 1 to 100 letters"
    "no_eq|# x\nsh b.sh\n|methods-no_eq.txt line 2: NAME: expected NAME=COMMAND"
    "no_cmd|x=  \n|methods-no_cmd.txt line 1: COMMAND: empty"
    "empty|# nothing\n\n|methods-empty.txt names no method")
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 tag)
  list(GET case 1 text)
  list(GET case 2 want)
  file(WRITE ${WORK}/methods-${tag}.txt "${text}")
  run(2 ${TRADEOFF} --trials 1 --seed 3 --levels 2d=8 --budget 0 --repeats 1
    --methods "closed-normal,@${WORK}/methods-${tag}.txt" --out ${WORK}/tradeoff-bad.csv)
  if(NOT err MATCHES "${want}")
    message(FATAL_ERROR "methods file ${tag}: '${err}' does not say '${want}'")
  endif()
endforeach()
run(2 ${TIMING} --methods "@${WORK}/no-such-file.txt" --out ${WORK}/t.csv)
if(NOT err MATCHES "no-such-file.txt cannot be opened")
  message(FATAL_ERROR "missing methods file: ${err}")
endif()
