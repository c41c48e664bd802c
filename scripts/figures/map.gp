# The fastest gait over the force plane (A/T0, c/T0): mean velocity of the best valid orbit
# (left) and of the best valid and stable orbit (right), from `capsubot sweep --optimize phi0`.
# Called by scripts/figures.sh with: term, out, valid_data, stable_data, T0, n (grid points
# per axis), lo, hi (grid range of A/T0 and c/T0).
set terminal term size 1500,700 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
d = (hi - lo) / (n - 1) / 2.0
set xrange [0:1]
set yrange [0:1]
set size ratio -1
set xlabel "force amplitude A / T_0"
set ylabel "mean force c / T_0"
set cblabel "mean velocity <v> of the fastest gait  [{/Symbol w}L]"
set palette defined (0 "#fde725", 0.25 "#5ec962", 0.5 "#21918c", 0.75 "#3b528b", 1 "#440154")
set grid front
set key top right box opaque font ",11"
set style fill solid 1.0 noborder
set object 1 rectangle from graph 0,0 to graph 1,1 back fc rgb "#d9d9d9" fillstyle solid 1.0 noborder
# A cell is coloured when the optimiser found an orbit (status ok) and that orbit is valid.
ok(c) = (strcol("status") eq "ok" && column("valid") == 1) ? c : NaN
stats valid_data using (ok(column("v_mean"))) nooutput
set cbrange [0:STATS_max]
set multiplot layout 1,2 title sprintf("Fastest one-impact gait, best impact phase {/Symbol f}_0 at each (A, c) (problem P1), T_0 = %g, e = 1.  Grey: no such orbit", T0)
set title "fastest valid orbit"
plot valid_data using (column("A")/T0):(ok(column("c")/T0)):(d):(d):(ok(column("v_mean"))) \
       with boxxyerror lc palette notitle, \
     1 - x with lines lw 2 dt 2 lc rgb "#000000" title "A + c = T_0"
set title "fastest valid and stable orbit (spectral radius < 1)"
plot stable_data using (column("A")/T0):(ok(column("c")/T0)):(d):(d):(ok(column("v_mean"))) \
       with boxxyerror lc palette notitle, \
     1 - x with lines lw 2 dt 2 lc rgb "#000000" title "A + c = T_0"
unset multiplot
