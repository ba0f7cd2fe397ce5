#!/usr/bin/env bash
# The main job: set-up (scripts/setup.sh), then the paper's runs with their figures, results
# files and a metrics table in out/paper/ (or the folder given as the first argument).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
.venv/bin/hinf-cpp paper --out "${1:-out/paper}"
