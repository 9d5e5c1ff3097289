# sidecar.gp - one number from a result's metadata sidecar ("key: value"
# lines in <result>.meta) into a gnuplot variable, NaN when the key is not
# there. The published numbers a figure compares with come this way: the
# driver records them (from the one table of the paper's numbers) in its
# sidecar, and the plot reads them here, so no .gp file holds one.
#   call 'plots/sidecar.gp' 'results/validation.csv' 'published_e_implicit_2d' 'pub_imp2'
# Leaves the datafile separator at comma.
set datafile separator whitespace
SIDECAR_records = 0; SIDECAR_max = NaN
stats ARG1 . '.meta' using (strcol(1) eq ARG2 . ':' ? column(2) : NaN) nooutput name 'SIDECAR'
eval sprintf("%s = SIDECAR_records > 0 ? SIDECAR_max : NaN", ARG3)
set datafile separator comma
