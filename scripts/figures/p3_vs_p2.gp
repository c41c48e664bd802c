# What more harmonics buy: the step I of the fastest valid gait against T0 with the best
# harmonic force (problem P2, `sweep --optimize forcing`, A + c <= T0) and the best force of
# 2 and 3 harmonics (problem P3, `sweep --optimize fourier --harmonics K`, max |F| <= T0), on
# the same log grid of T0 (e = 1). Rows whose optimiser did not end with a valid orbit are
# not drawn; `max_evaluations` (budget used up, point still valid) is drawn.
# Called by scripts/figures.sh with: term, out, p2, p3_2, p3_3 (the three CSVs).
set terminal term size 1000,650 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set logscale x
set xrange [0.008:1.25]
set xlabel "friction bound T_0 (force bound max|F| = T_0)"
set ylabel "step per period I of the fastest valid gait  [L]"
set yrange [0:*]
set grid
set key top left box opaque
ok(v) = (column("valid") == 1) ? v : NaN
set title "One harmonic (P2) against 2 and 3 harmonics (P3) at every T_0, e = 1"
plot p2 using "T0":(ok(column("I"))) with linespoints lw 2 pt 7 lc rgb "#440154" \
       title "P2: A sin({/Symbol f} + {/Symbol f}_0) + c", \
     p3_2 using "T0":(ok(column("I"))) with linespoints lw 2 pt 5 lc rgb "#21918c" \
       title "P3, 2 harmonics", \
     p3_3 using "T0":(ok(column("I"))) with linespoints lw 2 pt 9 lc rgb "#fde725" \
       title "P3, 3 harmonics"
