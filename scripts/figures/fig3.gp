# Fig. 3 of the paper: the step I per period against the impact phase phi0, for the paper's
# example (c = A = T0/2) and for a case with valid orbits (A/T0 = 0.2, c/T0 = 0.03).
# Called by scripts/figures.sh with: term, out, and for panel k = 1, 2: data_k, title_k,
# h_phi0_k, h_I_k (heuristic point), max_phi0_k, max_I_k (max of I), p1_phi0_k, p1_I_k (best
# valid orbit from --optimize phi0; NaN when there is none). P1 is the paper's problem: valid
# orbits with no margins and no stability requirement, so `optimize --problem phase`, whose
# defaults are the robust gait's margins and rho_max, answers another problem; the legend says so.
set terminal term size 1100,1250 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set xlabel "impact phase {/Symbol f}_0  [rad]"
set ylabel "step per period I  [L]"
set xrange [-pi:pi]
set xtics ("-{/Symbol p}" -pi, "-{/Symbol p}/2" -pi/2, "0" 0, "{/Symbol p}/2" pi/2, "{/Symbol p}" pi)
set grid
set key below box font ",11" maxrows 3 width -5
# An empty cell (no orbit) becomes NaN: the line breaks there instead of bridging the gap.
num(name) = strcol(name) eq "" ? NaN : column(name)
valid_only(c) = column("valid") == 1 ? c : NaN
stable_valid(c) = (column("valid") == 1 && column("stable") == 1) ? c : NaN
set multiplot layout 2,1 title "Fig. 3: step I of the one-impact orbit against the impact phase (e = 1)"
do for [k=1:2] {
  data = value(sprintf("data_%d", k))
  set title value(sprintf("title_%d", k))
  hx = value(sprintf("h_phi0_%d", k)); hy = value(sprintf("h_I_%d", k))
  mx = value(sprintf("max_phi0_%d", k)); my = value(sprintf("max_I_%d", k))
  px = value(sprintf("p1_phi0_%d", k)); py = value(sprintf("p1_I_%d", k))
  plot data using (column("phi0")):(num("I")) with lines lw 1.5 lc rgb "#7f7f7f" \
         title "every orbit (invalid ones included)", \
       data using (column("phi0")):(valid_only(column("I"))) with points pt 7 ps 0.5 lc rgb "#ff7f0e" \
         title "valid orbit, unstable", \
       data using (column("phi0")):(stable_valid(column("I"))) with points pt 7 ps 0.5 lc rgb "#2ca02c" \
         title "valid and stable orbit", \
       "+" using (hx):(hy) every ::0::0 with points pt 9 ps 2.2 lc rgb "#d62728" \
         title sprintf("paper's rule {/Symbol f}_0 + {/Symbol f}_1/2 = -{/Symbol p}/2: I = %.4g", hy), \
       "+" using (mx):(my) every ::0::0 with points pt 6 ps 2.2 lw 2 lc rgb "#1f77b4" \
         title sprintf("max of I over all orbits: I = %.4g at {/Symbol f}_0 = %.3f", my, mx), \
       "+" using (px):(py) every ::0::0 with points pt 4 ps 2.2 lw 2 lc rgb "#000000" \
         title (px == px ? sprintf("best valid orbit (P1: no margins, any stability): I = %.4g at {/Symbol f}_0 = %.3f", py, px) : "no valid orbit (P1 finds none)")
}
unset multiplot
