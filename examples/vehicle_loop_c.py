"""The exported C controller in a vehicle loop written in C (examples/vehicle_loop_c/main.c):
exports Figure 2's sampled controller (scenarios/paper_fig2_sampled.toml, as
`hinf-cpp export-controller` does), compiles it with the loop and the ship by the system's C
compiler (C99, the strict flags), runs it, and plots the CSV.

    python examples/vehicle_loop_c.py [OUT_DIR]    # default out/vehicle_loop_c

Writes OUT_DIR/controller/ (the exported folder), loop (the program), loop.csv (t, q, q_d, u at
every sample), loop_xy.png (the path: desired solid, actual dashed) and prints the RMS position
error over the last half. The C loop has its own noise generator, so its noise samples are not
hinf-cpp run's: compare the RMS error with the sampled scenario's (0.262 m, docs/online.md) as a
statistic, not digit by digit.
"""

from __future__ import annotations

import pathlib
import shutil
import subprocess
import sys

import numpy as np

import hinf_cpp as hc
from hinf_cpp.output.export_c import export_scenario

HERE = pathlib.Path(__file__).resolve().parent
FLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2"]


def build_and_run(out: pathlib.Path) -> pathlib.Path:
    exported = export_scenario(hc.load_scenario(hc.scenario_path("paper_fig2_sampled")), out / "controller")
    cc = shutil.which("cc")
    if cc is None:
        raise SystemExit("no C compiler (cc) on the PATH")
    folder = exported.folder
    program = out / "loop"
    subprocess.run([cc, *FLAGS, f"-I{folder}", "-o", str(program), str(HERE / "vehicle_loop_c" / "main.c"),
                    str(folder / "hinf_controller.c"), str(folder / "hinf_controller_tables.c"), "-lm"], check=True)
    csv = out / "loop.csv"
    done = subprocess.run([str(program), str(csv)], check=True, capture_output=True, text=True)
    print(done.stdout.strip())
    print(f"controller tables {exported.table_bytes} bytes, horizon [{exported.t0:g}, {exported.t_end:g}) s")
    return csv


def plot(csv: pathlib.Path, png: pathlib.Path) -> float:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = np.genfromtxt(csv, delimiter=",", names=True)
    error = np.hypot(data["x"] - data["x_d"], data["y"] - data["y_d"])
    half = data["t"] >= 0.5 * data["t"][-1]
    rms = float(np.sqrt(np.mean(error[half] ** 2)))
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(data["x_d"], data["y_d"], "-", label="desired")
    ax.plot(data["x"], data["y"], "--", label="ship, exported C controller")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal")
    ax.set_title(f"Figure 2 at 20 Hz in C: RMS error, last half {rms:.3f} m")
    ax.legend()
    fig.savefig(png, dpi=120, bbox_inches="tight")
    plt.close(fig)
    return rms


def main(argv: list[str]) -> int:
    out = pathlib.Path(argv[1] if len(argv) > 1 else "out/vehicle_loop_c")
    out.mkdir(parents=True, exist_ok=True)
    csv = build_and_run(out)
    rms = plot(csv, out / "loop_xy.png")
    print(f"RMS position error over the last half: {rms:.4f} m (wrote {out / 'loop.csv'}, {out / 'loop_xy.png'})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
