# Error against cost for one scene of the study, on log scales, with the Pareto front marked.
# Accuracy is up (the error axis runs downwards) and cost left, so the best methods are at the
# top left. Called by `gizmo study` as
#   gnuplot -e "datafile='pareto-S.csv'; frontfile='pareto-S-front.csv'; outfile='pareto-S.svg'; scene='S'" pareto.gp
# Data columns: family, label, cost (wall seconds per board second), error (L).
set terminal svg size 760,500 dynamic font "sans,11" background rgb "white"
set output outfile
set datafile separator ","
set logscale xy
set format x "1e%T"
set format y "1e%T"
set xlabel "cost: wall seconds per board second (left is cheaper)"
set ylabel "largest ball position error against the reference, L (up is more accurate)"
set yrange [*:*] reverse
set grid
set key outside right top
set title "error against cost: ".scene noenhanced
family(name) = strcol(1) eq name ? $4 : NaN
plot datafile using 3:(family("ballistic")) with points pt 7 ps 1.1 lc rgb "#1f77b4" title "ballistic (precisions)", \
     datafile using 3:(family("classic")) with points pt 9 ps 1.0 lc rgb "#2ca02c" title "classic (ticks x precisions)", \
     datafile using 3:(family("box2d")) with points pt 5 ps 1.0 lc rgb "#d62728" title "Box2D 2.4, bullets", \
     datafile using 3:(family("box2d-no-bullet")) with points pt 4 ps 1.0 lc rgb "#ff7f0e" title "Box2D 2.4, no bullets", \
     datafile using 3:(family("box2d-v3")) with points pt 13 ps 1.0 lc rgb "#9467bd" title "Box2D v3, bullets", \
     datafile using 3:(family("box2d-v3-no-bullet")) with points pt 12 ps 1.0 lc rgb "#8c564b" title "Box2D v3, no bullets", \
     frontfile using 3:4 with lines lw 1.5 dt 2 lc rgb "black" title "Pareto front", \
     frontfile using 3:4:2 with labels left offset 0.8,0.4 font ",8" noenhanced notitle
