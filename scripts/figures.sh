#!/usr/bin/env bash
# Regenerates the paper's figures into results/ (CSV from `capsubot sweep`, PNG from gnuplot):
#   every CSV starts with a '# capsubot <version> <command> ...' line (what made it):
#   gnuplot skips it, the awk helpers below read the table through `table`.
#   fig2_phi1_vs_phi0.{csv,png}   Fig. 2: phi1 against phi0 for c = A = T0/2
#   fig3_*.csv, fig3_I_vs_phi0.png Fig. 3: I against phi0, the paper's example and a valid case
#   map_valid.csv, map_stable.csv, map_best_velocity.png: the fastest gait over (A/T0, c/T0)
#   design_m2_*.csv, design_example.json, design_speed_power.png: the example robot's design
#   optimum.json                  the main job: `capsubot optimize -o results/optimum.json`
#   reach_from_rest.csv, reach_from_rest.png: the main job's promised and reached speeds
#   bifurcation_T0_*.csv, bifurcation_T0.png: long-run motions of the stable optimum's robot vs T0
#   basins_coexisting.{csv,png}: basins of a one-impact orbit and a period-12 motion
#   velocity_alpha.csv, velocity_alpha.png: multi-impact motions vs one-impact orbits over alpha
#   p2_T0_e.csv, p2_T0_e_stable.csv, p2_T0_e.png: the P2 optimum at every (T0, e)
#   reach_T0.csv, reach_T0.png: the fastest motion from rest at every T0 (sweep --optimize reach)
#   drives.json, drives_force.csv, drives_motion_K{1,2,3}.csv, drives.png: the fastest drives
#                                 from rest, the sine and Fourier series of 2 and 3 harmonics
#   drives_T0_*.json, drives_speed_{K,T0}.csv, drives_speed.png: their best speed against the
#                                 number of harmonics and against the frequency (T0)
#   loss_map.csv, loss_map_zoom.csv, loss_map.png: how the orbit loses stability over (phi0, A)
#   p3_vs_p2_forcing.csv, p3_vs_p2_fourier{2,3}.csv, p3_vs_p2.png: P2 against P3 over T0
#   three_axis_e_T0_phi0.csv, three_axis_e_T0_phi0.png: a 3-axis sweep (list, log, linear)
#   fourier_a2_b2.csv, fourier_a2_b2.png: P1 over a grid of second-harmonic coefficients
#   continuation_alpha_A{,_fold,_period_doubling}.csv, continuation_alpha_A.png: the fold and
#                                 the period doubling of a one-impact orbit followed in
#                                 (alpha, A) over the long-run motions of the same robots
# Usage, from anywhere, after building (scripts/build.sh):  scripts/figures.sh
# The program is $CAPSUBOT (default build/capsubot). Installs nothing: without gnuplot it
# writes the CSVs, says how to get gnuplot and exits with status 1.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${CAPSUBOT:-build/capsubot}
out=results
gp=scripts/figures
if [[ ! -x "$cli" ]]; then
  echo "figures: $cli not found: build it first with scripts/build.sh (or set CAPSUBOT)" >&2
  exit 1
fi
mkdir -p "$out"
say() { echo "figures: $*" >&2; }
table() { grep -v '^#' "$1"; }  # a CSV without its comment lines: header, then rows

# --- the data (every number of results/REPRODUCTION.md comes from these commands) ----------
say "the main job: the robust gait and the fastest motion from rest (docs/optimize.md)"
"$cli" optimize -o "$out/optimum.json" --from-rest-csv "$out/reach_from_rest.csv" > /dev/null

say "Fig. 2: phi1(phi0), c = A = T0/2"
"$cli" sweep --grid phi0=-pi:pi:721 --A 0.5 --c 0.5 --T0 1 -o "$out/fig2_phi1_vs_phi0.csv"

say "Fig. 3: I(phi0), the paper's example c = A = T0/2 and a case with valid orbits"
"$cli" sweep --grid phi0=-pi:pi:1441 --A 0.5 --c 0.5 --T0 1 --stability \
  -o "$out/fig3_paper_example.csv"
"$cli" sweep --grid phi0=-pi:pi:1441 --A 0.2 --c 0.03 --T0 1 --stability \
  -o "$out/fig3_valid_case.csv"
# P1 (best valid orbit) for both forces: a 2-point grid over A pairs each A with its c.
"$cli" sweep --grid A=0.5:0.5:1 --c 0.5 --T0 1 --optimize phi0 --stability \
  -o "$out/fig3_p1_paper_example.csv"
"$cli" sweep --grid A=0.2:0.2:1 --c 0.03 --T0 1 --optimize phi0 --stability \
  -o "$out/fig3_p1_valid_case.csv"

say "map: fastest valid gait and fastest valid and stable gait over (A/T0, c/T0), T0 = 0.1"
T0=0.1 n=50 lo=0.01 hi=0.99
A_grid="A=$(awk -v t=$T0 -v v=$lo 'BEGIN{print t*v}'):$(awk -v t=$T0 -v v=$hi 'BEGIN{print t*v}'):$n"
c_grid="c=$(awk -v t=$T0 -v v=$lo 'BEGIN{print t*v}'):$(awk -v t=$T0 -v v=$hi 'BEGIN{print t*v}'):$n"
"$cli" sweep --grid "$A_grid" --grid "$c_grid" --T0 $T0 --optimize phi0 --stability \
  -o "$out/map_valid.csv"
"$cli" sweep --grid "$A_grid" --grid "$c_grid" --T0 $T0 --optimize phi0 --stable-only \
  --stability -o "$out/map_stable.csv"

say "design: speed and power of the example robot (examples/robot.toml) against m2"
"$cli" design --config examples/robot.toml --rho-max inf --grid m2=0.002:0.5:400:log \
  -o "$out/design_m2_valid.csv"
"$cli" design --config examples/robot.toml --grid m2=0.002:0.5:400:log \
  -o "$out/design_m2_robust.csv"
"$cli" design --config examples/robot.toml --json > "$out/design_example.json.tmp"
mv "$out/design_example.json.tmp" "$out/design_example.json"
# Long-run motions (docs/attractors.md). The robot of the stable optimum at T0 = 1, e = 1
# (`optimize --problem forcing --stable --json`, no margins).
robot="--A 0.34063197373861814 --c 0.06410131873607934 --phi0 -3.1181183398453047 --e 1"
say "bifurcation diagram of the stable optimum's robot against T0"
"$cli" bifurcation $robot --alpha 0.6435592358295166 --param T0 --from 0.45 --to 2 --steps 311 \
  --start 0.5,1 -o "$out/bifurcation_T0_impacts.csv" --summary "$out/bifurcation_T0_summary.csv"
say "mean velocity against alpha: multi-impact motions and one-impact orbits"
small="--A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5"  # a force with valid one-impact orbits
"$cli" bifurcation $small --param alpha --from 0.05 --to 0.95 --steps 181 --start 0.5,1 \
  --max-period 16 -o "$out/velocity_alpha_impacts.csv" --summary "$out/velocity_alpha.csv"

say "P2 per point: the fastest gait (best A, c, phi0 with A + c <= T0) over (T0, e)"
n_T0=17
T0_grid="T0=0.01:1:$n_T0:log" e_grid="e=0:1:11"
"$cli" sweep --grid "$T0_grid" --grid "$e_grid" --optimize forcing --stability \
  -o "$out/p2_T0_e.csv"
"$cli" sweep --grid "$T0_grid" --grid "$e_grid" --optimize forcing --stable-only --stability \
  -o "$out/p2_T0_e_stable.csv"
say "reach per point: the fastest motion from rest at 7 values of T0 (about a minute of CPU)"
"$cli" sweep --grid T0=0.05:1:7:log --optimize reach -o "$out/reach_T0.csv"

say "the fastest drives from rest: Fourier series of 1, 2, 3 harmonics, max |F| <= T0 (reach.md)"
"$cli" optimize --problem reach --harmonics 3 --reach-seconds 1000000 -o "$out/drives.json" > /dev/null
/usr/bin/python3 "$gp/drives.py" force "$out/drives.json" "$out/drives_force.csv"
for k in 1 2 3; do
  read -r -a drive <<< "$(/usr/bin/python3 "$gp/drives.py" args "$out/drives.json" "$k")"
  "$cli" simulate "${drive[@]}" --x0 0.5 --u0 0 --v0 0 --transient 200 --periods 2 \
    --samples-per-period 400 --trajectory "$out/drives_motion_K$k.csv" > /dev/null
done

say "the best speed against the frequency: the ladder to K = 2 at 4 more values of T0 (about a minute and a half)"
for T0 in 0.125 0.25 0.5 2; do
  "$cli" optimize --problem reach --harmonics 2 --T0 $T0 --reach-seconds 1000000 \
    -o "$out/drives_T0_$T0.json" > /dev/null
done
/usr/bin/python3 "$gp/drives.py" speed "$out/drives_speed_K.csv" "$out/drives_speed_T0.csv" \
  "$out/drives.json" "$out"/drives_T0_{0.125,0.25,0.5,2}.json

# The other kinds of sweep (docs/sweep.md, "Figures"): a few seconds of CPU together.
say "stability loss (stable, fold, flip, torus) over (phi0, A): all, and the torus corner"
loss="--c 0.002 --T0 0.1 --e 1 --stability"
"$cli" sweep --grid A=0.001:0.098:41:log --grid phi0=-pi:pi:181 $loss -o "$out/loss_map.csv"
"$cli" sweep --grid A=0.086:0.098:25 --grid phi0=-2.6:-2.0:61 $loss -o "$out/loss_map_zoom.csv"
say "P2 against P3 with 2 and 3 harmonics at 13 values of T0"
"$cli" sweep --grid T0=0.01:1:13:log --optimize forcing -o "$out/p3_vs_p2_forcing.csv"
for k in 2 3; do
  "$cli" sweep --grid T0=0.01:1:13:log --optimize fourier --harmonics $k \
    -o "$out/p3_vs_p2_fourier$k.csv"
done
say "a 3-axis sweep: a list of e, a log grid of T0, a linear grid of phi0"
"$cli" sweep --grid e=0.5,0.75,1 --grid T0=0.07:1:21:log --grid phi0=-pi:pi:121 --A 0.05 \
  --c 0.02 -o "$out/three_axis_e_T0_phi0.csv"
say "P1 over a grid of second-harmonic coefficients (a2, b2)"
"$cli" sweep --grid a2=-0.03:0.03:31 --grid b2=-0.03:0.03:31 --A 0.05 --c 0.02 --T0 0.1 \
  --optimize phi0 --stability -o "$out/fourier_a2_b2.csv"

say "curves of special points in (alpha, A) over the long runs of the same robots (~10 s)"
curve_robot="$small --alpha 0.2792869076315278 --from-orbit --param alpha --from 0.12 --to 0.4"
for follow in fold period_doubling; do
  "$cli" continue $curve_robot --param2 A --from2 0.02 --to2 0.08 --follow $follow \
    -o "$out/continuation_alpha_A_$follow.csv" > /dev/null
done
impacts=$(mktemp)  # the bifurcation's impacts (-o) are not kept: the map is its summary
"$cli" bifurcation $small --param alpha --from 0.12 --to 0.4 --steps 101 --over A=0.02:0.08:41 \
  --start 0.5,1 --no-analytic -o "$impacts" --summary "$out/continuation_alpha_A.csv"
rm -f "$impacts"

# --- marks read off the CSVs ----------------------------------------------------------------
# The paper's rule phi0 + phi1/2 = -pi/2: the first row pair where h = phi0 + phi1/2 + pi/2
# changes sign, interpolated linearly (NaN when h keeps its sign).
heuristic() {  # prints "phi0 I"
  awk -F, 'NR > 1 && $2 != "" { h = $1 + $2 / 2 + atan2(0, -1) / 2
             if (NR > 2 && ph * h <= 0 && ph != h) { t = ph / (ph - h)
               printf "%.10g %.10g\n", p0 + t * ($1 - p0), pI + t * ($6 - pI); found = 1; exit }
             ph = h; p0 = $1; pI = $6 }
           END { if (!found) print "NaN NaN" }' <(table "$1")
}
max_I() {  # prints "phi0 I" of the largest I
  awk -F, 'NR > 1 && $6 != "" && (!n++ || $6 > m) { m = $6; p = $1 } END { print p, m }' \
    <(table "$1")
}
p1() {  # prints "phi0 I" of the optimiser's answer if it is a valid orbit
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i }
           NR == 2 { if ($col["status"] == "ok" && $col["valid"] == 1) print $col["phi0"], $col["I"]
                     else print "NaN NaN" }' <(table "$1")
}

if ! command -v gnuplot > /dev/null 2>&1; then
  say "gnuplot is not installed: the CSVs are in $out/, the PNGs were not made."
  say "install it with: scripts/install-deps.sh --figures   (Debian package gnuplot-nox)"
  exit 1
fi
term=png
if gnuplot -e "set terminal pngcairo" > /dev/null 2>&1; then term=pngcairo; fi

read -r h0 h1 < <(awk -F, 'NR > 1 { h = $1 + $2 / 2 + atan2(0, -1) / 2
   if (NR > 2 && ph * h <= 0 && ph != h) { t = ph / (ph - h)
     printf "%.10g %.10g\n", p0 + t * ($1 - p0), q1 + t * ($2 - q1); exit }
   ph = h; p0 = $1; q1 = $2 }' <(table "$out/fig2_phi1_vs_phi0.csv"))
gnuplot -e "term='$term'; data='$out/fig2_phi1_vs_phi0.csv'; out='$out/fig2_phi1_vs_phi0.png'; h_phi0=$h0; h_phi1=$h1" \
  "$gp/fig2.gp"

read -r hx1 hy1 < <(heuristic "$out/fig3_paper_example.csv")
read -r mx1 my1 < <(max_I "$out/fig3_paper_example.csv")
read -r px1 py1 < <(p1 "$out/fig3_p1_paper_example.csv")
read -r hx2 hy2 < <(heuristic "$out/fig3_valid_case.csv")
read -r mx2 my2 < <(max_I "$out/fig3_valid_case.csv")
read -r px2 py2 < <(p1 "$out/fig3_p1_valid_case.csv")
gnuplot -e "term='$term'; out='$out/fig3_I_vs_phi0.png';
  data_1='$out/fig3_paper_example.csv'; title_1=\"paper's example: c = A = T_0/2, T_0 = 1\";
  h_phi0_1=$hx1; h_I_1=$hy1; max_phi0_1=$mx1; max_I_1=$my1; p1_phi0_1=$px1; p1_I_1=$py1;
  data_2='$out/fig3_valid_case.csv'; title_2=\"a case with valid orbits: A = 0.2 T_0, c = 0.03 T_0, T_0 = 1\";
  h_phi0_2=$hx2; h_I_2=$hy2; max_phi0_2=$mx2; max_I_2=$my2; p1_phi0_2=$px2; p1_I_2=$py2" \
  "$gp/fig3.gp"

gnuplot -e "term='$term'; out='$out/map_best_velocity.png'; valid_data='$out/map_valid.csv';
  stable_data='$out/map_stable.csv'; T0=$T0; n=$n; lo=$lo; hi=$hi" "$gp/map.gp"
gnuplot -e "term='$term'; data='$out/reach_from_rest.csv'; out='$out/reach_from_rest.png'" \
  "$gp/reach.gp"
read -r dm2 dspeed dpower < <(python3 -c 'import json, sys
g = json.load(sys.stdin)["one_impact"]
print(g["m2_kg"], g["speed_mm_s"], g["power_mw"])' < "$out/design_example.json")
gnuplot -e "term='$term'; out='$out/design_speed_power.png'; valid_data='$out/design_m2_valid.csv';
  robust_data='$out/design_m2_robust.csv'; best_m2=$dm2; best_speed=$dspeed; best_power=$dpower" \
  "$gp/design.gp"
gnuplot -e "term='$term'; out='$out/bifurcation_T0.png'; impacts='$out/bifurcation_T0_impacts.csv';
  summary='$out/bifurcation_T0_summary.csv';
  title_text='Long-run motions of one robot against the friction bound T_0 (F = 0.3406 sin({/Symbol f} - 3.1181) + 0.0641, {/Symbol a} = 0.6436, e = 1)'" \
  "$gp/bifurcation.gp"
gnuplot -e "term='$term'; out='$out/velocity_alpha.png'; summary='$out/velocity_alpha.csv';
  title_text='Long-run motions and one-impact orbits against the mass ratio {/Symbol a} (F = 0.05 sin({/Symbol f} - 2.842) + 0.02, T_0 = 0.1, e = 0.5)'" \
  "$gp/velocity_alpha.gp"
say "basins of two coexisting attractors (drawn by capsubot basins through gnuplot)"
"$cli" basins $small --alpha 0.2792869076315278 \
  --max-period 16 --transient 1000 --starts 128x128 -o "$out/basins_coexisting.csv" \
  --plot "$out/basins_coexisting.png"
gnuplot -e "term='$term'; out='$out/p2_T0_e.png'; valid_data='$out/p2_T0_e.csv';
  stable_data='$out/p2_T0_e_stable.csv'; n_T0=$n_T0" "$gp/p2_T0_e.gp"
gnuplot -e "term='$term'; data='$out/reach_T0.csv'; out='$out/reach_T0.png'" "$gp/reach_T0.gp"
speeds=$(/usr/bin/python3 -c "import json,sys; l=json.load(open(sys.argv[1]))['ladder']; \
print('; '.join('v%d=%r' % (s['harmonics'], s['mean_velocity']) for s in l))" "$out/drives.json")
gnuplot -e "term='$term'; out='$out/drives.png'; force='$out/drives_force.csv';
  motion1='$out/drives_motion_K1.csv'; motion2='$out/drives_motion_K2.csv';
  motion3='$out/drives_motion_K3.csv'; $speeds" "$gp/drives.gp"
pulse=$(/usr/bin/python3 -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['pulse']['mean_velocity']))" "$out/optimum.json")
gnuplot -e "term='$term'; out='$out/drives_speed.png'; by_K='$out/drives_speed_K.csv';
  by_T0='$out/drives_speed_T0.csv'; pulse=$pulse" "$gp/drives_speed.gp"
gnuplot -e "term='$term'; out='$out/loss_map.png'; data='$out/loss_map.csv';
  zoom='$out/loss_map_zoom.csv'; c=0.002; T0=0.1; e=1; dphi=pi/180; A_lo=0.001; A_hi=0.098;
  rA=$(awk 'BEGIN { print exp(log(98) / 40) }'); phi_lo=-2.6; phi_hi=-2.0; zphi=0.005;
  zA_lo=0.086; zA_hi=0.098; zA=0.00025" "$gp/loss_map.gp"
gnuplot -e "term='$term'; out='$out/p3_vs_p2.png'; p2='$out/p3_vs_p2_forcing.csv';
  p3_2='$out/p3_vs_p2_fourier2.csv'; p3_3='$out/p3_vs_p2_fourier3.csv'" "$gp/p3_vs_p2.gp"
gnuplot -e "term='$term'; out='$out/three_axis_e_T0_phi0.png'; data='$out/three_axis_e_T0_phi0.csv';
  A=0.05; c=0.02; dphi=pi/120; rT=$(awk 'BEGIN { print exp(log(1 / 0.07) / 20) }'); T_lo=0.07;
  T_hi=1; e1=0.5; e2=0.75; e3=1" "$gp/three_axis.gp"
gnuplot -e "term='$term'; out='$out/fourier_a2_b2.png'; data='$out/fourier_a2_b2.csv';
  A=0.05; c=0.02; T0=0.1; e=1; d=0.001" "$gp/fourier_a2_b2.gp"
gnuplot -e "term='$term'; out='$out/continuation_alpha_A.png'; map='$out/continuation_alpha_A.csv';
  fold='$out/continuation_alpha_A_fold.csv'; flip='$out/continuation_alpha_A_period_doubling.csv';
  da=0.0014; dA=0.00075; a_lo=0.12; a_hi=0.4; A_lo=0.02; A_hi=0.08; robot_alpha=0.2792869076315278;
  robot_A=0.05; title_text='The one-impact orbit of F = A sin({/Symbol f} - 2.842) + 0.02 (T_0 = 0.1, e = 0.5): its fold and period doubling followed in ({/Symbol a}, A)'" \
  "$gp/continuation_alpha_A.gp"
say "done: $(cd "$out" && ls fig2_* fig3_* drives_* map_* reach_* p2_* design_* bifurcation_* velocity_* basins_* loss_* p3_* three_* fourier_* continuation_* | tr '\n' ' ')"
