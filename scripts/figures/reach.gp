# What the main job's robot reaches from rest: the robust one-impact gait's promised mean
# velocity, the mean velocities of the attractors it reaches from rest, and those of the fastest
# motion from rest, each bar labelled with the fraction of starts that end there.
# Called by scripts/figures.sh with: term, data (the CSV of `capsubot optimize --from-rest-csv`),
# out.
set terminal term size 1100,650 font ",13"
set output out
set datafile separator ","
set datafile columnheaders
set style fill solid 0.85 border -1
set boxwidth 0.7
set ylabel "mean velocity  [{/Symbol w}L]"
set yrange [0:*]
set offsets 0.8, 0.8, 0.05, 0
set bmargin 4
set grid ytics
set key top left box opaque
set title "The main job's robot: the speed its one-impact gait promises and the speeds it reaches from rest (T_0 = 1, e = 1, A + c ≤ T_0)" font ",12"
# Row k of the file (header excluded) is bar k; the label is the fraction of starts.
is(g, r) = (strcol("gait") eq g && strcol("row") eq r)
label(r) = strcol("row") eq "promised" ? "promised" : sprintf("%.0f %% of starts", 100.0 * column("fraction"))
per(p) = p == 1 ? "per period" : sprintf("per %d periods", p)
walls(r, l) = l == 0 ? sprintf("%d right", r) : sprintf("%d right + %d left", r, l)
motion(r) = strcol("row") eq "promised" ? "1 right impact\nper period" : \
  sprintf("%s impacts\n%s", walls(column("impacts_right"), column("impacts_left")), per(column("period")))
plot data using ($0):(is("robust", "promised") ? column("mean_velocity") : NaN) with boxes \
       lc rgb "#bdbdbd" title "robust one-impact gait: promised by the orbit", \
     data using ($0):(is("robust", "attractor") ? column("mean_velocity") : NaN) with boxes \
       lc rgb "#3b528b" title "robust gait: reached from rest", \
     data using ($0):(is("reach", "attractor") ? column("mean_velocity") : NaN) with boxes \
       lc rgb "#21918c" title "fastest motion from rest", \
     data using ($0):(column("mean_velocity")):(label(0)) with labels offset 0,1 notitle, \
     data using ($0):(0):xtic(motion(0)) with points pt -1 notitle
