# The best speed from rest against the number of harmonics K and against the frequency.
# Left: mean velocity from rest (omega L) at T0 = 1 for K = 1, 2, 3 and the 3-level pulse drive,
# all under max |F| <= T0. Right: the physical speed v_mean / sqrt(T0) (units of sqrt(mu g L):
# the motor's frequency free, the force bound the friction force) against T0 for K = 1 and 2.
# Called by scripts/figures.sh with: term, by_K (drives_speed_K.csv: K, mean_velocity at
# T0 = 1), by_T0 (drives_speed_T0.csv: T0, speed_K1, speed_K2, ...), pulse (the pulse drive's
# mean velocity at T0 = 1), out.
set terminal term size 1200,550 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set multiplot layout 1,2 title "The fastest drives from rest under max |F| <= T_0 (e = 1)" font ",14"
set grid
set key top left box opaque
set xlabel "harmonics K of the force"
set ylabel "mean velocity from rest [{/Symbol w}L]"
set xrange [0.5:3.5]
set xtics 1
set yrange [0:*]
plot by_K using "K":"mean_velocity" with linespoints lw 2 pt 7 ps 1.5 lc rgb "#21918c" title "Fourier, T_0 = 1", \
     "+" using (3):(pulse) every ::0::0 with points pt 5 ps 2 lc rgb "#d62728" title sprintf("pulse of 3 levels: %.3f", pulse)
set xlabel "friction bound T_0 = {/Symbol m}g/({/Symbol w}^2 L)  (lower: faster motor)"
set ylabel "speed v_{mean}/sqrt(T_0) [sqrt({/Symbol m}gL)]"
set logscale x 2
set xrange [*:*]
set xtics auto
plot by_T0 using "T0":"speed_K1" with linespoints lw 2 pt 7 ps 1.2 lc rgb "#440154" title "sine (K = 1)", \
     by_T0 using "T0":"speed_K2" with linespoints lw 2 pt 9 ps 1.4 lc rgb "#21918c" title "K = 2"
unset multiplot
