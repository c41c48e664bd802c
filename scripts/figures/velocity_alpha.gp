# Mean velocity against the mass ratio alpha for one force: the long-run motions of the up and
# down sweeps (coloured by right-wall impacts per forcing period) against the valid analytic
# one-impact orbits, from `capsubot bifurcation --param alpha --summary`.
# Called by scripts/figures.sh with: term, out, summary, title_text.
set terminal term size 1200,700 font ",12"
set output out
set datafile separator ","
set datafile columnheaders
set title title_text noenhanced
set key top left box opaque
set grid
set xlabel "mass ratio {/Symbol a} = m_2/(m_1+m_2)"
set ylabel "mean velocity <v> [{/Symbol w}L]"
set cblabel "right-wall impacts per forcing period"
set palette defined (0 "#440154", 1 "#3b528b", 2 "#21918c", 3 "#5ec962", 4 "#fde725")
set cbrange [0:4]
is(dir) = strcol("direction") eq dir
per(c) = column("period") > 0 ? column(c) / column("period") : column(c) / 100.0
orbit(stable) = (is("analytic") && (column("spectral_radius") < 1) == stable) ? column("mean_velocity") : NaN
plot summary using "param":((is("up") || is("down")) ? column("mean_velocity") : NaN):(per("impacts_right")) \
       with points pt 7 ps 0.6 lc palette title "long-run motion from rest (sweeps up and down)", \
     summary using "param":(orbit(1)) with points pt 5 ps 0.7 lc rgb "#d62728" title "one-impact orbit, stable", \
     summary using "param":(orbit(0)) with points pt 4 ps 0.7 lc rgb "#ff9896" title "one-impact orbit, unstable"
