# One kernel chart of the study from gizmo_bench's figures: a point per category (along x) and
# series (colour), with a bar of one standard deviation over the repetitions and a label beside it
# (a ratio). Called by `gizmo study --bench` as
#   gnuplot -e "datafile='kernels-C.csv'; ticsfile='kernels-C-tics.gp'; outfile='kernels-C.svg'; title='T'; ylabel='Y'; logy=0|1; refline=R; reflabel='L'; width=W" kernels.gp
# Data columns: category index (from 0), series index (from 1), value, standard deviation, label.
# The tics file names the categories (x tics), sets the ranges, and holds nseries and the array
# `names` of the series' titles. refline > 0 draws a dashed line at that value (1: the baseline).
set encoding utf8
set terminal svg size width,480 dynamic font "sans,11" background rgb "white"
set output outfile
set datafile separator ","
load ticsfile
if (logy) { set logscale y; set format y "10^{%T}" }
# Rotated up to the left, each name ending at its tick: long names stay inside the picture.
set xtics nomirror rotate by 20 right font ",10"
set ylabel ylabel noenhanced
set title title noenhanced
set grid ytics
set key outside right top noenhanced
# The line is an arrow across the graph, named in the key rather than on the graph, where a
# label would cover points.
if (refline > 0) {
  set arrow from graph 0, first refline to graph 1, first refline nohead dt 2 lw 1.2 lc rgb "black"
}
# The series side by side within a category, so that their bars do not overlap.
shift(s) = (s - (nseries + 1) / 2.0) * 0.7 / nseries
in(s) = $2 == s ? $3 : NaN
points = "for [s=1:nseries] datafile using ($1 + shift(s)):(in(s)):4 with yerrorbars pt 7 ps 0.9 lw 1.2 lc s title names[s], ".\
         "for [s=1:nseries] datafile using ($1 + shift(s)):(in(s)):5 with labels left offset 0.5,0.5 font ',8' noenhanced notitle"
if (refline > 0) {
  eval "plot ".points.", keyentry with lines dt 2 lw 1.2 lc rgb 'black' title reflabel"
} else {
  eval "plot ".points
}
