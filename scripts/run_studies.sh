#!/usr/bin/env bash
# The shipped studies (studies/*.toml, docs/studies.md), each into its folder under out/studies/
# (or the folder given as the first argument): runs.parquet, runs.csv, summary.md and figures.
# About 4 minutes on 2 cores. An interrupted run resumes where it stopped (OUT/NAME/partial/).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT="${1:-out/studies}"
HINF_CPP="${HINF_CPP:-.venv/bin/hinf-cpp}"
for study in fig2_monte_carlo model_uncertainty region_of_attraction gamma_sweep turn_around; do
  "$HINF_CPP" study "studies/$study.toml" --out "$OUT/$study"
done
