# A 3-axis sweep drawn as small multiples: `capsubot sweep --grid e=<list> --grid T0=...:log
# --grid phi0=...` for one force F = A sin(phi + phi0) + c; one panel per value of the list
# axis e, each the step I of the valid orbits over (phi0, T0). Invalid orbits grey, no
# orbit white.
# Called by scripts/figures.sh with: term, out, data, A, c, dphi (half the phi0 step), rT
# (T0 is log-spaced: neighbours differ by the factor rT), T_lo, T_hi, e1, e2, e3.
set terminal term size 1600,620 font ",12"
set output out
set datafile separator ","
set datafile columnheaders
set xrange [-pi:pi]
set xtics ("-{/Symbol p}" -pi, "-{/Symbol p}/2" -pi/2, "0" 0, "{/Symbol p}/2" pi/2, "{/Symbol p}" pi)
set logscale y
set yrange [T_lo / sqrt(rT):T_hi * sqrt(rT)]
set xlabel "impact phase {/Symbol f}_0  [rad]"
set ylabel "friction bound T_0"
set cblabel "step per period I  [L]"
set palette defined (0 "#fde725", 0.25 "#5ec962", 0.5 "#21918c", 0.75 "#3b528b", 1 "#440154")
set style fill solid 1.0 noborder
set grid front
ok(v) = (column("valid") == 1) ? v : NaN
orbit(v) = (strcol("alpha") eq "" || column("valid") == 1) ? NaN : v
stats data using (ok(column("I"))) nooutput
set cbrange [0:STATS_max]
set multiplot layout 1,3 title sprintf("A 3-axis sweep, one panel per value of the list axis e: F = %g sin({/Symbol f} + {/Symbol f}_0) + %g", A, c)
do for [ev in sprintf("%g %g %g", e1, e2, e3)] {
  set title sprintf("e = %s", ev)
  if (ev + 0 == e3) { set colorbox } else { unset colorbox }  # one colour bar, the last panel's
  plot data using "phi0":(abs(column("e") - ev) < 1e-12 ? orbit(column("T0")) : NaN):(column("phi0")-dphi):(column("phi0")+dphi):(column("T0")/sqrt(rT)):(column("T0")*sqrt(rT)) \
         with boxxyerror fc rgb "#c8c8c8" notitle, \
       data using "phi0":(abs(column("e") - ev) < 1e-12 ? ok(column("T0")) : NaN):(column("phi0")-dphi):(column("phi0")+dphi):(column("T0")/sqrt(rT)):(column("T0")*sqrt(rT)):(ok(column("I"))) \
         with boxxyerror lc palette notitle
}
unset multiplot
