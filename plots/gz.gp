# gz.gp - reading results stored compressed. Large raw results are kept as
# *.csv.gz (Makefile.paper's NAME_OUT); plot and stats read them through a
# pipe, the metadata sidecar is <file>.meta either way.
#   load 'plots/gz.gp'
#   data = gzdata(results)       the file itself, or "< gzip -dc 'FILE'"
#   gzcat(results)               a shell command printing the CSV text
gzdata(f) = (strlen(f) > 3 && f[strlen(f)-2:] eq '.gz') ? "< gzip -dc '" . f . "'" : f
gzcat(f) = sprintf("gzip -dcf '%s'", f)
