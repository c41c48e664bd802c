# The fastest motion from rest against T0 (`capsubot sweep --optimize reach`): the mean
# velocity the winner reaches from rest, beside the robust one-impact gait it was seeded with,
# as its orbit promises and as the robot reaches it from rest.
# Called by scripts/figures.sh with: term, data (the CSV of the reach sweep), out.
set terminal term size 1000,620 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set logscale x
set xrange [0.04:1.2]
set xlabel "friction bound T_0"
set ylabel "mean velocity  [{/Symbol w}L]"
set grid
set key top left box opaque
set title "Fastest motion from rest at every T_0 (e = 1, A + c <= T_0)"
plot data using "T0":"mean_velocity" with linespoints lw 2 pt 7 lc rgb "#21918c" \
       title "fastest motion from rest (reach)", \
     data using "T0":"seed_v_mean" with linespoints lw 2 pt 5 dt 2 lc rgb "#bdbdbd" \
       title "robust one-impact gait: promised by its orbit", \
     data using "T0":"seed_mean_velocity_from_rest" with linespoints lw 2 pt 9 \
       lc rgb "#3b528b" title "robust gait: reached from rest"
