# How the one-impact orbit loses stability over (phi0, A) at fixed c, T0, e: each valid orbit
# coloured by the `loss` column of `capsubot sweep --stability` (stable, fold: the largest
# multiplier through +1, flip: through -1, torus: a complex pair leaves the unit circle);
# invalid orbits grey, no orbit white. Left the whole phase range, right a zoom on the corner
# where the torus kind occurs (A + c close to T0).
# Called by scripts/figures.sh with: term, out, data, zoom, c, T0, e; the whole grid: dphi
# (half the phi0 step), A_lo, A_hi, rA (A is log-spaced: neighbours differ by the factor rA);
# the zoom grid: phi_lo, phi_hi, zphi (half step), zA_lo, zA_hi, zA (half step).
set terminal term size 1500,700 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set xlabel "impact phase {/Symbol f}_0  [rad]"
set ylabel "force amplitude A"
set grid front
set style fill solid 1.0 noborder
set key below horizontal box opaque font ",12"
# Colour of a row: an orbit without alpha (no mass ratio closes it) is not drawn.
kind(s) = (column("valid") == 0) ? 0xc8c8c8 : (column("stable") == 1) ? 0x2ca02c : \
  (s eq "fold") ? 0x1f77b4 : (s eq "flip") ? 0xd62728 : (s eq "torus") ? 0xff7f0e : 0x000000
has_orbit(y) = (strcol("alpha") eq "") ? NaN : y
set multiplot layout 1,2 title sprintf("How the one-impact orbit loses stability: F = A sin({/Symbol f} + {/Symbol f}_0) + %g,  T_0 = %g,  e = %g", c, T0, e)
set title "whole phase range"
set xrange [-pi:pi]
set xtics ("-{/Symbol p}" -pi, "-{/Symbol p}/2" -pi/2, "0" 0, "{/Symbol p}/2" pi/2, "{/Symbol p}" pi)
set logscale y
set yrange [A_lo / sqrt(rA):A_hi * sqrt(rA)]
plot data using "phi0":(has_orbit(column("A"))):(column("phi0")-dphi):(column("phi0")+dphi):(column("A")/sqrt(rA)):(column("A")*sqrt(rA)):(kind(strcol("loss"))) \
       with boxxyerror lc rgb variable notitle, \
     NaN with boxes fs solid lc rgb "#2ca02c" title "stable", \
     NaN with boxes fs solid lc rgb "#1f77b4" title "fold (+1)", \
     NaN with boxes fs solid lc rgb "#d62728" title "flip (-1)", \
     NaN with boxes fs solid lc rgb "#ff7f0e" title "torus (complex pair)", \
     NaN with boxes fs solid lc rgb "#c8c8c8" title "invalid orbit", \
     NaN with boxes fs empty border lc rgb "#000000" lc rgb "#000000" title "no orbit"
unset key
set title "zoom: A + c close to T_0"
unset logscale y
set xtics auto
set xrange [phi_lo - zphi:phi_hi + zphi]
set yrange [zA_lo - zA:zA_hi + zA]
plot zoom using "phi0":(has_orbit(column("A"))):(column("phi0")-zphi):(column("phi0")+zphi):(column("A")-zA):(column("A")+zA):(kind(strcol("loss"))) \
       with boxxyerror lc rgb variable notitle
unset multiplot
