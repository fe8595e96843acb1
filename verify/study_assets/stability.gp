# The stability map: for every stress scene (rows), which methods (columns, each family from its
# coarsest parameter to its finest) agree with the reference, fail (a ball more than the fail
# distance off, or a wrong decision) or stop. Called by `gizmo study` as
#   gnuplot -e "datafile='stability.csv'; ticsfile='stability-tics.gp'; outfile='stability.svg'; width=W; height=H" stability.gp
# Data columns: column index, row index, status (0 agrees, 1 fails, 2 stopped).
set terminal svg size width,height dynamic font "sans,11" background rgb "white"
set output outfile
set datafile separator ","
load ticsfile
set xtics rotate by -60 font ",9" nomirror
set ytics font ",10" nomirror
set palette defined (0 "#4caf50", 1 "#ff9800", 2 "#d62728")
set cbrange [0:2]
unset colorbox
set key outside top center horizontal
set title "where each method fails on the stress scenes" noenhanced
plot datafile using 1:2:(0.45):(0.45):3 with boxxyerror fs solid 1.0 noborder lc palette notitle, \
     NaN with boxes fs solid lc rgb "#4caf50" title "agrees", \
     NaN with boxes fs solid lc rgb "#ff9800" title "fails", \
     NaN with boxes fs solid lc rgb "#d62728" title "stops"
