# Bifurcation diagram against T0 of a robot: impact velocities of the recorded right-wall impacts
# (top) and mean velocity (bottom) of the up and down sweeps, from
# `capsubot bifurcation --param T0`.
# Called by scripts/figures.sh with: term, out, impacts, summary, title_text.
set terminal term size 1200,1000 font ",12"
set output out
set datafile separator ","
set datafile columnheaders
set multiplot layout 2,1 title title_text
# Keys sit outside the axes, so that no key covers a branch.
set key below horizontal box
set lmargin 12
set grid
set xlabel "friction bound T_0"
set ylabel "impact velocity u at the right wall [{/Symbol w}L]"
is(dir) = strcol("direction") eq dir
right(dir) = (is(dir) && strcol("wall") eq "right") ? column("velocity") : NaN
plot impacts using "param":(right("up")) with points pt 7 ps 0.3 lc rgb "#1f77b4" title "sweep up (T_0 increasing)", \
     impacts using "param":(right("down")) with points pt 7 ps 0.3 lc rgb "#d62728" title "sweep down (T_0 decreasing)"
set ylabel "mean velocity <v> [{/Symbol w}L]"
sweep(dir) = is(dir) ? column("mean_velocity") : NaN
plot summary using "param":(sweep("up")) with points pt 7 ps 0.5 lc rgb "#1f77b4" title "sweep up (T_0 increasing)", \
     summary using "param":(sweep("down")) with points pt 6 ps 0.7 lc rgb "#d62728" title "sweep down (T_0 decreasing)"
unset multiplot
