"""The exported C controller's step against the C++ online controller's, on the same log.

    python benchmarks/bench_export.py [--rounds 7] [--out benchmarks/results/export]

Figure 2 on the 20 Hz computer (scenarios/paper_fig2_sampled.toml: gamma = 5, T = 0.05 s, a
20 ms computation delay, bounds and rate limits): its controller exported to C
(hinf_cpp.output.export_c), output feedback (the sampled update) and the same design with
state feedback. A log of 800 samples: each measurement taken at t_k and answered at t_k + 20 ms
(so each step predicts over 20 ms, and the output-feedback step over the 50 ms since the last
measurement too); x, y, psi with noise of sigma = 0.5, or the full state.

Two small programs replay the log, each call of step timed alone (clock_gettime / steady_clock,
monotonic): one compiled from the exported folder (cc -O2 -std=c99), one against the installed
C++ package (the wheel's hinf_core, the same design built as benchmarks/bench_online.cpp builds
it: the ship, gamma = 5, emulated at 0.05 s; c++ -O2). Each program replays the log 200 times per
run and prints the median and 99th percentile of its calls; the runs alternate (C, C++, C, C++
...) so that a change of the machine's load falls on both; printed: the median over the runs.
The load average is written beside the numbers.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile

import numpy as np

import hinf_cpp as hc
from hinf_cpp.output.export_c import export_controller, export_scenario

C_DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "hinf_controller.h"

static int compare(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

int main(int argc, char **argv) {
  static hinf_controller_state controller;
  static double t_now[800], t_meas[800], v[800][HINF_MEASUREMENT_SIZE], seconds[200 * 800];
  double q0[HINF_N], u[HINF_M], sink = 0.0;
  int count, i, j, round, rounds = atoi(argv[2]);
  FILE *f = fopen(argv[1], "r");
  if (f == NULL || fscanf(f, "%d", &count) != 1 || count > 800) return 2;
  for (i = 0; i < HINF_N; ++i)
    if (fscanf(f, "%lf", &q0[i]) != 1) return 2;
  for (i = 0; i < count; ++i) {
    if (fscanf(f, "%lf %lf", &t_now[i], &t_meas[i]) != 2) return 2;
    for (j = 0; j < HINF_MEASUREMENT_SIZE; ++j)
      if (fscanf(f, "%lf", &v[i][j]) != 1) return 2;
  }
  fclose(f);
  for (round = 0; round < rounds; ++round) {
    hinf_controller_init(&controller);
    hinf_controller_reset(&controller, HINF_T0, q0, NULL);
    for (i = 0; i < count; ++i) {
      struct timespec a, b;
      clock_gettime(CLOCK_MONOTONIC, &a);
      hinf_controller_step(&controller, t_now[i], v[i], t_meas[i], u);
      clock_gettime(CLOCK_MONOTONIC, &b);
      seconds[round * count + i] = (b.tv_sec - a.tv_sec) + 1e-9 * (b.tv_nsec - a.tv_nsec);
      sink += u[0];
    }
  }
  qsort(seconds, (size_t)(rounds * count), sizeof(double), compare);
  printf("%.6g %.6g %g\n", seconds[rounds * count / 2] * 1e6, seconds[(size_t)(0.99 * (rounds * count - 1))] * 1e6,
         sink);
  return 0;
}
"""

CPP_DRIVER = r"""
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "hinf/control/online_controller.hpp"
#include "hinf/control/riccati.hpp"
#include "hinf/models/ship.hpp"

using namespace hinf;

int main(int argc, char** argv) {
  const bool output_feedback = std::atoi(argv[2]) != 0;
  const int rounds = std::atoi(argv[3]);
  Vec q_d0 = Vec::Zero(6);
  q_d0(0) = 1.0;
  const VectorSignal u_d(std::vector<Signal>{Signal(1.0), Signal(0.0, {Harmonic{0.3, 0.2, 0.0, false}})});
  const auto trajectory = std::make_shared<const Trajectory>(std::make_shared<const ShipModel>(), q_d0, u_d, 0.0, 40.0);
  const auto design = solve_grde(trajectory, Mat::Identity(6, 6), Mat::Identity(6, 6), 5.0);
  OnlineOptions options;
  options.limits.u_min = Vec::Constant(2, -3.0);
  options.limits.u_max = Vec::Constant(2, 3.0);
  options.limits.rate_max = Vec::Constant(2, 20.0);
  if (output_feedback) {
    options.filter.N = 0.25 * Mat::Identity(3, 3);
    options.filter.Sigma0 = Mat::Identity(6, 6);
    options.filter.Q = Mat::Identity(6, 6);
  }
  OnlineController controller(SampledLaw::emulated(design, 0.05), options);
  const int size = controller.measurement_size();
  std::FILE* f = std::fopen(argv[1], "r");
  int count = 0;
  Vec q0(6), u(2);
  if (f == nullptr || std::fscanf(f, "%d", &count) != 1) return 2;
  for (int i = 0; i < 6; ++i)
    if (std::fscanf(f, "%lf", &q0[i]) != 1) return 2;
  std::vector<double> t_now(count), t_meas(count), v(static_cast<std::size_t>(count) * size);
  for (int i = 0; i < count; ++i) {
    if (std::fscanf(f, "%lf %lf", &t_now[i], &t_meas[i]) != 2) return 2;
    for (int j = 0; j < size; ++j)
      if (std::fscanf(f, "%lf", &v[static_cast<std::size_t>(i) * size + j]) != 1) return 2;
  }
  std::fclose(f);
  std::vector<double> seconds;
  seconds.reserve(static_cast<std::size_t>(rounds) * count);
  double sink = 0.0;
  for (int round = 0; round < rounds; ++round) {
    controller.reset(0.0, q0);
    for (int i = 0; i < count; ++i) {
      const auto a = std::chrono::steady_clock::now();
      controller.step(t_now[i], &v[static_cast<std::size_t>(i) * size], t_meas[i], u.data());
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
      sink += u[0];
    }
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%.6g %.6g %g\n", seconds[seconds.size() / 2] * 1e6,
              seconds[static_cast<std::size_t>(0.99 * (seconds.size() - 1))] * 1e6, sink);
  return 0;
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.16)
project(bench_export_cpp CXX)
find_package(hinf_cpp CONFIG REQUIRED)
add_executable(replay_cpp replay.cpp)
target_compile_features(replay_cpp PRIVATE cxx_std_17)
target_link_libraries(replay_cpp PRIVATE hinf_cpp::hinf_core)
"""


def write_log(path: pathlib.Path, q0, t_now, t_meas, rows) -> None:
    lines = [str(len(t_now)), " ".join(repr(float(x)) for x in q0)]
    lines += [f"{float(a)!r} {float(b)!r} " + " ".join(repr(float(x)) for x in row)
              for a, b, row in zip(t_now, t_meas, rows)]
    path.write_text("\n".join(lines) + "\n")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7, help="runs of each program (alternating)")
    parser.add_argument("--out", default="benchmarks/results/export", help="results: OUT.txt and OUT.json")
    args = parser.parse_args(argv[1:])
    cc, cxx, cmake = shutil.which("cc"), shutil.which("c++"), shutil.which("cmake")
    if cc is None or cxx is None or cmake is None:
        raise SystemExit("needs cc, c++ and cmake on the PATH")
    work = pathlib.Path(tempfile.mkdtemp(prefix="bench-export-"))
    scenario = hc.load_scenario(hc.scenario_path("paper_fig2_sampled"))
    result = hc.run_scenario(scenario)
    of = export_scenario(scenario, work / "of")
    sf = export_controller(result.solution, work / "sf", period=0.05,
                           options=hc.OnlineOptions(limits=scenario.sampling.limits))
    t_meas = 0.05 * np.arange(800)
    t_now = t_meas + 0.02
    q = result.simulation.q[::5][:800]
    rng = np.random.default_rng(20000601)
    y = q[:, 3:6] + 0.5 * rng.standard_normal((800, 3))
    write_log(work / "of.log", result.trajectory.q_d0(), t_now, t_meas, y)
    write_log(work / "sf.log", scenario.initial_q0, t_now, t_meas, q + 0.01 * rng.standard_normal(q.shape))
    for exported, name in ((of, "of"), (sf, "sf")):
        folder = exported.folder
        (work / f"{name}.c").write_text(C_DRIVER)
        subprocess.run([cc, "-std=c99", "-O2", f"-I{folder}", "-o", str(work / f"replay_c_{name}"),
                        str(work / f"{name}.c"), str(folder / "hinf_controller.c"),
                        str(folder / "hinf_controller_tables.c"), "-lm"], check=True)
    cpp = work / "cpp"
    cpp.mkdir()
    (cpp / "replay.cpp").write_text(CPP_DRIVER)
    (cpp / "CMakeLists.txt").write_text(CMAKE)
    package = subprocess.run([sys.executable, "-m", "hinf_cpp.cmake"], capture_output=True, text=True,
                             check=True).stdout.strip()
    subprocess.run([cmake, "-S", str(cpp), "-B", str(cpp / "build"), "-DCMAKE_BUILD_TYPE=Release",
                    f"-Dhinf_cpp_DIR={package}"], check=True, capture_output=True)
    subprocess.run([cmake, "--build", str(cpp / "build")], check=True, capture_output=True)
    replay_cpp = cpp / "build" / "replay_cpp"

    load_before = pathlib.Path("/proc/loadavg").read_text().split()[:3]
    samples: dict[str, list[tuple[float, float]]] = {k: [] for k in ("c_sf", "cpp_sf", "c_of", "cpp_of")}
    for _ in range(args.rounds):
        for key, command in (("c_sf", [str(work / "replay_c_sf"), str(work / "sf.log"), "200"]),
                             ("cpp_sf", [str(replay_cpp), str(work / "sf.log"), "0", "200"]),
                             ("c_of", [str(work / "replay_c_of"), str(work / "of.log"), "200"]),
                             ("cpp_of", [str(replay_cpp), str(work / "of.log"), "1", "200"])):
            out = subprocess.run(command, capture_output=True, text=True, check=True).stdout.split()
            samples[key].append((float(out[0]), float(out[1])))
    load_after = pathlib.Path("/proc/loadavg").read_text().split()[:3]
    summary = {key: {"median_us": statistics.median(m for m, _ in runs), "p99_us": statistics.median(p for _, p in runs)}
               for key, runs in samples.items()}
    lines = [f"step of the exported C controller and of the C++ OnlineController, the same 800-sample log, "
             f"{args.rounds} alternating runs x 200 replays each; load average before {' '.join(load_before)}, "
             f"after {' '.join(load_after)}",
             f"{'case':<40} {'C median us':>12} {'C++ median us':>14} {'C p99 us':>10} {'C++ p99 us':>11} {'C / C++':>8}"]
    for label, key in (("state feedback, predicted 20 ms", "sf"), ("output feedback (sampled update)", "of")):
        c, cxx_ = summary[f"c_{key}"], summary[f"cpp_{key}"]
        lines.append(f"{label:<40} {c['median_us']:12.3f} {cxx_['median_us']:14.3f} {c['p99_us']:10.3f} "
                     f"{cxx_['p99_us']:11.3f} {c['median_us'] / cxx_['median_us']:8.2f}")
    lines.append(f"tables: output feedback {of.table_bytes} bytes, state feedback {sf.table_bytes} bytes")
    text = "\n".join(lines) + "\n"
    print(text, end="")
    out = pathlib.Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.with_suffix(".txt").write_text(text)
    out.with_suffix(".json").write_text(json.dumps({"load_before": load_before, "load_after": load_after,
                                                    "rounds": args.rounds, "summary": summary,
                                                    "runs": samples}, indent=2) + "\n")
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
