# Fig. 2 of the paper: the stop phase phi1 against the impact phase phi0 for c = A = T0/2.
# Called by scripts/figures.sh with: term, data, out, h_phi0, h_phi1 (the heuristic point).
set terminal term size 900,620 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set title "Fig. 2: stop phase {/Symbol f}_1 against impact phase {/Symbol f}_0   (c = A = T_0/2, e = 1)"
set xlabel "impact phase {/Symbol f}_0  [rad]"
set ylabel "stop phase {/Symbol f}_1  [rad]"
set xrange [-pi:pi]
set yrange [0:*]
set xtics ("-{/Symbol p}" -pi, "-{/Symbol p}/2" -pi/2, "0" 0, "{/Symbol p}/2" pi/2, "{/Symbol p}" pi)
set grid
set key bottom left Left reverse box opaque
plot data using (column("phi0")):(column("phi1")) with lines lw 2.5 lc rgb "#1f77b4" \
       title "{/Symbol f}_1({/Symbol f}_0): first root of the stop equation (paper eq. 4.3)", \
     "+" using (h_phi0):(h_phi1) every ::0::0 with points pt 7 ps 1.8 lc rgb "#d62728" \
       title sprintf("paper's example: {/Symbol f}_0 + {/Symbol f}_1/2 = -{/Symbol p}/2, {/Symbol f}_1 = %.3f, {/Symbol f}_0 = %.3f", h_phi1, h_phi0)
