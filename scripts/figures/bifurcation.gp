# Bifurcation diagram against T0 of a robot: impact velocities of the recorded right-wall impacts
# (top) and mean velocity (bottom) of the up and down sweeps, with the valid analytic one-impact
# orbits (filled: stable, open: unstable), from `capsubot bifurcation --param T0`.
# Called by scripts/figures.sh with: term, out, impacts, summary, title_text.
set terminal term size 1200,1000 font ",12"
set output out
set datafile separator ","
set datafile columnheaders
set multiplot layout 2,1 title title_text noenhanced
set key top right box opaque
set grid
set xlabel "friction bound T_0"
set ylabel "impact velocity u at the right wall [{/Symbol w}L]"
is(dir) = strcol("direction") eq dir
right(dir) = (is(dir) && strcol("wall") eq "right") ? column("velocity") : NaN
plot impacts using "param":(right("up")) with points pt 7 ps 0.3 lc rgb "#1f77b4" title "sweep up", \
     impacts using "param":(right("down")) with points pt 7 ps 0.3 lc rgb "#d62728" title "sweep down"
set ylabel "mean velocity <v> [{/Symbol w}L]"
sweep(dir) = is(dir) ? column("mean_velocity") : NaN
orbit(stable) = (is("analytic") && (column("spectral_radius") < 1) == stable) ? column("mean_velocity") : NaN
plot summary using "param":(sweep("up")) with points pt 7 ps 0.5 lc rgb "#1f77b4" title "sweep up", \
     summary using "param":(sweep("down")) with points pt 6 ps 0.7 lc rgb "#d62728" title "sweep down", \
     summary using "param":(orbit(1)) with points pt 5 ps 0.6 lc rgb "#000000" title "one-impact orbit, stable", \
     summary using "param":(orbit(0)) with points pt 4 ps 0.6 lc rgb "#7f7f7f" title "one-impact orbit, unstable"
unset multiplot
