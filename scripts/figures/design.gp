# Designing the example robot (examples/robot.toml): mean speed and mean motor power of the
# one-impact gait against the inner mass m2, from `capsubot design --sweep m2:...`.
# Called by scripts/figures.sh with: term, out, valid_data (no stability requirement),
# robust_data (default robust-gait margins), best_m2, best_speed, best_power (the design).
set terminal term size 1000,900 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set logscale x
set format x "%g"
set xrange [0.002:0.5]
set grid
# The key sits bottom left, where neither panel has data (every gait lies right of 0.008 kg).
set key bottom left box opaque font ",11"
set lmargin 12  # both panels share the x axis
set style line 1 lw 2 dt 2 lc rgb "#7f7f7f"
set style line 2 lw 3 lc rgb "#1f77b4"
set style line 3 pt 7 ps 1.8 lc rgb "#d62728"
# A row has a gait when its status is ok (other cells are empty then).
ok(v) = strcol("status") eq "ok" ? v : NaN
set multiplot layout 2,1 title "Example robot: m_1 = 0.2 kg, L = 20 mm, {/Symbol m} = 0.3, e = 0.7, motor 0.5 sin({/Symbol w}t) + 0.1 N at 20 Hz"
set ylabel "mean speed  [mm/s]"
set yrange [0:*]
unset xlabel
plot valid_data using (column("m2_kg")):(ok(column("speed_mm_s"))) with lines ls 1 \
       title "fastest valid one-impact orbit (unstable left of 0.21 kg)", \
     robust_data using (column("m2_kg")):(ok(column("speed_mm_s"))) with lines ls 2 \
       title "robust gait ({/Symbol r}_{max} = 0.9)", \
     "+" using (best_m2):(best_speed) every ::0::0 with points ls 3 \
       title sprintf("design: m_2 = %.4g kg, %.3g mm/s", best_m2, best_speed)
set ylabel "mean motor power  [mW]"
set xlabel "inner mass m_2  [kg]"
plot valid_data using (column("m2_kg")):(ok(column("power_mw"))) with lines ls 1 \
       title "fastest valid one-impact orbit", \
     robust_data using (column("m2_kg")):(ok(column("power_mw"))) with lines ls 2 \
       title "robust gait ({/Symbol r}_{max} = 0.9)", \
     "+" using (best_m2):(best_power) every ::0::0 with points ls 3 \
       title sprintf("design: %.3g mW", best_power)
unset multiplot
