# Two-parameter curves of special points over the brute-force map they bound: the long-run
# motions of `capsubot bifurcation --param alpha --over A` (one cell per (alpha, A), coloured by
# the motion the sweep settles on: the one-impact orbit, its period-2 motion, another periodic
# motion, none found), left the sweep up in alpha, right the sweep down; over them the fold and
# the period doubling of the one-impact orbit followed in (alpha, A) by `capsubot continue
# --param2 A`, and the robot both curves start from.
# Called by scripts/figures.sh with: term, out, map, fold, flip, da, dA (half the alpha and A
# steps of the map), a_lo, a_hi, A_lo, A_hi, robot_alpha, robot_A, title_text.
set terminal term size 1500,800 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set xlabel "mass ratio {/Symbol a}"
set ylabel "force amplitude A"
set bmargin 8
set grid front
set style fill solid 1.0 noborder
set key below horizontal maxrows 2 box opaque font ",12" samplen 2
motion(dummy) = (strcol("status") ne "periodic") ? 0xc8c8c8 : \
  (column("period") == 1 && column("impacts_right") == 1 && column("impacts_left") == 0) ? 0x98df8a : \
  (column("period") == 2 && column("impacts_right") == 2 && column("impacts_left") == 0) ? 0xffbb78 : 0xc6dbef
in(dir, y) = (strcol("direction") eq dir) ? y : NaN
set xrange [a_lo - da:a_hi + da]
set yrange [A_lo - dA:A_hi + dA]
set multiplot layout 1,2 title title_text
do for [dir in "up down"] {
  set title sprintf("long runs, sweep %s in {/Symbol a} (state carried from value to value)", dir)
  plot map using "param":(in(dir, column("A"))):(column("param")-da):(column("param")+da):(column("A")-dA):(column("A")+dA):(motion(0)) \
         with boxxyerror lc rgb variable notitle, \
       NaN with boxes fs solid lc rgb "#98df8a" title "one-impact orbit", \
       NaN with boxes fs solid lc rgb "#ffbb78" title "period 2", \
       NaN with boxes fs solid lc rgb "#c6dbef" title "other periodic", \
       NaN with boxes fs solid lc rgb "#c8c8c8" title "no period", \
       fold using "alpha":"A" with lines lw 3 lc rgb "#1f77b4" title "fold", \
       flip using "alpha":"A" with lines lw 3 lc rgb "#d62728" title "period doubling", \
       "+" using (robot_alpha):(robot_A) every ::0::0 with points pt 7 ps 1.6 lc rgb "#000000" \
         title "start"
}
unset multiplot
