# The fastest drives from rest under one bound max |F| <= T0 (T0 = 1, e = 1): one period of the
# force of each winner (the sine, K = 2, K = 3 harmonics), the inner body's position in the shell
# and the shell's position over two periods after 200 periods from rest (x0 = 0.5, psi = 0).
# Called by scripts/figures.sh with: term, force (drives_force.csv), motion1..motion3 (the
# trajectories of `capsubot simulate --trajectory`), v1..v3 (the mean velocities from rest over
# 64 starts), out.
set terminal term size 1100,1100 font ",13"
set encoding utf8
set output out
set datafile separator ","
set datafile columnheaders
set multiplot layout 3,1 title sprintf("The fastest drives from rest, max |F| <= T_0 = 1, e = 1: sine %.3f, K = 2 %.3f, K = 3 %.3f {/Symbol w}L", v1, v2, v3) font ",14"
set grid
set key outside right box opaque
set xlabel "phase {/Symbol f} (one forcing period)"
set ylabel "force F / T_0"
set xrange [0:2*pi]
set yrange [-1.1:1.1]
plot force using "phi":"F_K1" with lines lw 2 lc rgb "#440154" title "sine", \
     force using "phi":"F_K2" with lines lw 2 lc rgb "#21918c" title "K = 2", \
     force using "phi":"F_K3" with lines lw 2 lc rgb "#fde725" title "K = 3"
# The last two periods of each run (the files hold the 200 periods of transient too), the
# phase counted from their start, the shell's position from its position there.
t0 = 400 * pi
in(c) = column("phi") >= t0 ? column(c) : NaN
set autoscale
stats motion1 using (in("y")) nooutput
y1 = STATS_min
stats motion2 using (in("y")) nooutput
y2 = STATS_min
stats motion3 using (in("y")) nooutput
y3 = STATS_min
set xlabel "phase {/Symbol f} over two periods, after 200 periods from rest"
set ylabel "inner body x (walls at 0 and 1)"
set xrange [0:4*pi]
set yrange [-0.05:1.05]
plot motion1 using (column("phi") - t0):(in("x")) with lines lw 2 lc rgb "#440154" title "sine", \
     motion2 using (column("phi") - t0):(in("x")) with lines lw 2 lc rgb "#21918c" title "K = 2", \
     motion3 using (column("phi") - t0):(in("x")) with lines lw 2 lc rgb "#fde725" title "K = 3"
set ylabel "shell displacement y [L]"
set autoscale y
plot motion1 using (column("phi") - t0):(in("y") - y1) with lines lw 2 lc rgb "#440154" title "sine", \
     motion2 using (column("phi") - t0):(in("y") - y2) with lines lw 2 lc rgb "#21918c" title "K = 2", \
     motion3 using (column("phi") - t0):(in("y") - y3) with lines lw 2 lc rgb "#fde725" title "K = 3"
unset multiplot
