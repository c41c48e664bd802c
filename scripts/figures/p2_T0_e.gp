# The fastest gait at every (T0, e): problem P2 (best A, c, phi0 with A + c <= T0) solved at
# each point of a grid by `capsubot sweep --optimize forcing`; left the fastest valid gait,
# right the fastest valid and stable one. Colour: the step I (gap lengths per period).
# Called by scripts/figures.sh with: term, out, valid_data, stable_data, n_T0 (log-spaced T0
# points from 0.01 to 1).
set terminal term size 1500,700 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set logscale x
set xrange [0.0075:1.33]
set yrange [-0.05:1.05]
set xlabel "friction bound T_0 = {/Symbol m}g/({/Symbol w}^2L)"
set ylabel "restitution e"
set cblabel "step I of the fastest gait  [L per period]"
set logscale cb
set format cb "%g"
set palette defined (0 "#fde725", 0.25 "#5ec962", 0.5 "#21918c", 0.75 "#3b528b", 1 "#440154")
set style fill solid 1.0 noborder
set object 1 rectangle from graph 0,0 to graph 1,1 back fc rgb "#d9d9d9" fillstyle solid 1.0 noborder
# T0 is log-spaced (n_T0 points over two decades): neighbours differ by the factor r.
r = 10**(2.0/(n_T0 - 1))
ok(v) = (strcol("status") eq "ok" && column("valid") == 1) ? v : NaN
set multiplot layout 1,2 title "Fastest one-impact gait at each (T_0, e): problem P2 at every grid point.  Grey: none found"
set title "fastest valid gait"
plot valid_data using (column("T0")):(ok(column("e"))):(column("T0")/sqrt(r)):(column("T0")*sqrt(r)):(column("e")-0.05):(column("e")+0.05):(ok(column("I"))) \
       with boxxyerror lc palette notitle
set title "fastest valid and stable gait (spectral radius <= 1)"
plot stable_data using (column("T0")):(ok(column("e"))):(column("T0")/sqrt(r)):(column("T0")*sqrt(r)):(column("e")-0.05):(column("e")+0.05):(ok(column("I"))) \
       with boxxyerror lc palette notitle
unset multiplot
