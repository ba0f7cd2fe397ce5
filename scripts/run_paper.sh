#!/usr/bin/env bash
# The main job: set-up (scripts/setup.sh), then the paper's runs with their figures (the x-y
# paths, and per law the tracking errors and the inputs against time), results files and a
# metrics table in out/paper/ (or the folder given as the first argument), an animation of
# Figure 1 (fig1_run.gif, docs/results.md; about a second), and the
# built-in vehicles' runs (docs/vehicles.md) in its subfolder vehicles/ and the planned
# scenarios (docs/planning.md) in planned/ (a few seconds more each), and a small study (50 noise
# seeds of Figure 2 per law, docs/studies.md) in studies/quick_monte_carlo/ (a few seconds; the
# full shipped studies take minutes: scripts/run_studies.sh), and the sampled-data loops of
# examples/online_loop.py (the online controller at 20 and 5 Hz, emulated and digital design, a
# one-sample delay) in online_loop.txt, and Figure 2 on a 20 Hz vehicle computer
# (scenarios/paper_fig2_sampled.toml: delay, actuator limits) in sampled/ (a few seconds), and
# the same controller exported as C99 and run in a vehicle loop written in C
# (examples/vehicle_loop_c.py, docs/export.md) in exported/ (a few seconds), and an hour's
# mission and Figure 2 over the receding horizon (docs/online.md) in receding/ (a few seconds).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
OUT="${1:-out/paper}"
.venv/bin/hinf-cpp paper --out "$OUT"
.venv/bin/hinf-cpp animate scenarios/paper_fig1.toml -o "$OUT/fig1_run.gif"
.venv/bin/hinf-cpp vehicles --out "$OUT/vehicles"
.venv/bin/hinf-cpp planned --out "$OUT/planned"
.venv/bin/hinf-cpp study studies/quick_monte_carlo.toml --out "$OUT/studies/quick_monte_carlo"
# Written beside, then renamed: an interrupted run leaves the previous file whole.
.venv/bin/python examples/online_loop.py >"$OUT/online_loop.txt.partial"
mv "$OUT/online_loop.txt.partial" "$OUT/online_loop.txt"
.venv/bin/hinf-cpp run scenarios/paper_fig2_sampled.toml --json "$OUT/sampled/paper_fig2_sampled.json" \
  --csv "$OUT/sampled/paper_fig2_sampled.csv" --plot "$OUT/sampled/paper_fig2_sampled.png"
# The exported controller in a C loop: built in a folder beside, then renamed over the old one.
rm -rf "$OUT/exported.partial"
.venv/bin/python examples/vehicle_loop_c.py "$OUT/exported.partial" >"$OUT/exported.partial.txt"
mv "$OUT/exported.partial.txt" "$OUT/exported.partial/summary.txt"
rm -rf "$OUT/exported"
mv "$OUT/exported.partial" "$OUT/exported"
# Missions of any length: an hour under the receding horizon with the path changed at 1800 s, and
# Figure 2 on the 20 Hz computer over the receding horizon (a few seconds).
.venv/bin/hinf-cpp run scenarios/mission_hour.toml --json "$OUT/receding/mission_hour.json" \
  --plot "$OUT/receding/mission_hour.png"
.venv/bin/hinf-cpp run scenarios/paper_fig2_receding.toml --json "$OUT/receding/paper_fig2_receding.json" \
  --plot "$OUT/receding/paper_fig2_receding.png"
