# plot.cmake - the body of timing.plot: plots/timing.gp on a result file
# written here, with a method no list knows ("my-method") beside a registry
# one in 2D SQ, and in 3D EE a method whose name would be Greek in
# gnuplot's enhanced text ("my_method"), and seven more in 3D SQ so that
# the data hold more than 8 methods (as the registry does). The figure,
# drawn as SVG, must key a curve by each of those names as they are, and
# gnuplot must not fail.
# cmake -DGNUPLOT=... -DPLOT=plots/timing.gp -DWORK=<scratch> -P plot.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(rows "dim,case,method,level,points_per_body,trial,status,seconds,points_out,trials_planned,trials_run,warmup_seconds\n")
foreach(n 10 20 40)
  string(APPEND rows "2,SQ,my-method,${n},${n},0,ok,${n}e-5,${n},2,2,0\n")
  string(APPEND rows "2,SQ,my-method,${n},${n},1,ok,${n}e-6,${n},2,2,0\n")
  string(APPEND rows "2,SQ,closed-gradient,${n},${n},0,ok,${n}e-6,${n},1,1,0\n")
  math(EXPR points "${n} * ${n}")
  string(APPEND rows "3,EE,my_method,${n},${points},0,ok,1e-3,${points},3,1,0\n")
  foreach(k 3 4 5 6 7 8 9)
    string(APPEND rows "3,SQ,method-${k},${n},${points},0,ok,${k}e-4,${points},1,1,0\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/timing.csv "${rows}")
execute_process(COMMAND ${GNUPLOT} -e "results='${WORK}/timing.csv'; outdir='${WORK}'; formats='svg'" ${PLOT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/timing.svg)
  message(FATAL_ERROR "plots/timing.gp failed (${rc}): ${out}${err}")
endif()
file(READ ${WORK}/timing.svg svg)
foreach(name my-method closed-gradient my_method method-3 method-8 method-9)
  string(FIND "${svg}" "<text>${name}</text>" at)
  if(at LESS 0)
    message(FATAL_ERROR "the figure has no key entry '${name}' (see ${WORK}/timing.svg)")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
