# A grid over Fourier coefficients: the best impact phase (problem P1, `sweep --optimize
# phi0`) for the motor force F = c + A sin s + a2 cos 2s + b2 sin 2s (motor phase s = phi +
# phi0, docs/model.md section 7) at every (a2, b2); colour the step I of the best valid
# orbit, grey where P1 found none. The cross marks the one-harmonic force (a2 = b2 = 0).
# Called by scripts/figures.sh with: term, out, data, A, c, T0, e, d (half the grid step).
set terminal term size 900,760 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set size ratio -1
set xlabel "a_2  (coefficient of cos 2s, s = motor phase)"
set ylabel "b_2  (coefficient of sin 2s)"
set cblabel "step per period I of the best valid orbit  [L]"
set palette defined (0 "#fde725", 0.25 "#5ec962", 0.5 "#21918c", 0.75 "#3b528b", 1 "#440154")
set style fill solid 1.0 noborder
set grid front
set key below box opaque
set object 1 rectangle from graph 0,0 to graph 1,1 back fc rgb "#c8c8c8" fillstyle solid 1.0 noborder
ok(v) = (strcol("status") eq "ok" && column("valid") == 1) ? v : NaN
stats data using "a2" nooutput
set xrange [STATS_min - d:STATS_max + d]
stats data using "b2" nooutput
set yrange [STATS_min - d:STATS_max + d]
set title sprintf("Best impact phase (P1) with a second harmonic: A = %g, c = %g, T_0 = %g, e = %g.  Grey: no valid orbit", A, c, T0, e) font ",12"
plot data using "a2":(ok(column("b2"))):(d):(d):(ok(column("I"))) with boxxyerror lc palette notitle, \
     "+" using (0):(0) every ::0::0 with points pt 2 ps 2.5 lw 3 lc rgb "#d62728" title "one harmonic (a_2 = b_2 = 0)"
