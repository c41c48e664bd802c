# Mean velocity against the mass ratio alpha for one force: the long-run motions of the up and
# down sweeps (coloured by right-wall impacts per forcing period) against the valid analytic
# one-impact orbits, from `capsubot bifurcation --param alpha --summary`.
# Called by scripts/figures.sh with: term, out, summary, title_text.
set terminal term size 1200,700 font ",12"
set output out
set datafile separator ","
set datafile columnheaders
set title title_text
set key top right box opaque
set grid
set xlabel "mass ratio {/Symbol a} = m_2/(m_1+m_2)"
set ylabel "mean velocity <v> [{/Symbol w}L]"
set cblabel "right-wall impacts per forcing period"
# A discrete scale: one colour per count, counts of 4 and more share the last colour.
set palette defined (0 "#440154", 1 "#3b528b", 2 "#21918c", 3 "#5ec962", 4 "#fde725")
set palette maxcolors 5
set cbrange [-0.5:4.5]
set cbtics ("0" 0, "1" 1, "2" 2, "3" 3, "≥ 4" 4)
is(dir) = strcol("direction") eq dir
per(c) = (column("period") > 0 ? column(c) / column("period") : column(c) / 100.0)
capped(c) = per(c) > 4 ? 4 : per(c)
orbit(stable) = (is("analytic") && (column("spectral_radius") < 1) == stable) ? column("mean_velocity") : NaN
plot summary using "param":((is("up") || is("down")) ? column("mean_velocity") : NaN):(capped("impacts_right")) \
       with points pt 7 ps 0.6 lc palette notitle, \
     NaN with points pt 7 ps 0.8 lc rgb "#3b528b" title "long-run motion from rest, sweeps up and down (colour: impacts)", \
     summary using "param":(orbit(1)) with points pt 5 ps 0.7 lc rgb "#d62728" title "one-impact orbit, stable", \
     summary using "param":(orbit(0)) with points pt 4 ps 0.7 lc rgb "#ff9896" title "one-impact orbit, unstable"
