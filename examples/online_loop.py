"""A control loop at a fixed rate, as on a vehicle: the online controller called once per sample,
the plant simulated separately (here a fixed-step Runge-Kutta of the ship's own equations).

The paper's Figure-1 run (the ship, u_d = [1, 0.3 sin 0.2t], the paper's disturbance, start 1 m
behind and 1 m aside with a 45 degree heading error): every T seconds the state is measured, the
controller answers with a command, and the command is held until the next sample, optionally
applied one sample late (a computation delay the controller knows of and predicts over). With
output feedback (Figure 2's set-up) only x, y, psi are measured, with noise of standard deviation
0.5 per sample (seeded), and the controller runs the estimator and the H-infinity filter (with
the digital law, the discrete game's own filter).

    python examples/online_loop.py            # prints the RMS position error of each loop

The continuous loop (run_scenario of paper_fig1.toml) gives 0.0479 m; Figure 2's continuous loop
with its noise held 0.05 s gives 0.265 m (docs/online.md).
"""

from __future__ import annotations

import numpy as np

import hinf_cpp as hc


def paper_design(tf: float = 40.0):
    u_d = [1.0, hc.Signal(0.0, [hc.Harmonic(amplitude=0.3, omega=0.2)])]
    trajectory = hc.Trajectory(hc.ShipModel(), [1, 0, 0, 0, 0, 0], u_d, 0.0, tf)
    return trajectory, hc.solve_grde(trajectory, np.eye(6), np.eye(6), 5.0)


def disturbance(t: float) -> np.ndarray:
    """The paper's w: 0.1 cos(2 pi 0.2 t) on the three forces, zero on the noise channels."""
    force = 0.1 * np.cos(2 * np.pi * 0.2 * t)
    return np.array([force, force, force, 0.0, 0.0, 0.0])


def run_loop(trajectory, law, period: float, delayed: bool = False, sigma: float | None = None, seed: int = 1,
             tf: float = 40.0, h: float = 0.005) -> float:
    """The RMS position error over the second half of [0, tf] (m) of the sampled loop: at
    t_k = k T the state is measured (with `sigma`: only x, y, psi, plus noise of that standard
    deviation per sample, and the controller is the output-feedback one); the command computed
    from it is applied from t_k (or from t_{k+1} when delayed) and held."""
    ship = trajectory.model()
    limits = hc.ActuatorLimits(u_min=[-5, -5], u_max=[5, 5])
    q = np.array([1.0, 0.0, 0.0, -1.0, -1.0, np.pi / 4])
    rng = np.random.default_rng(seed)
    if sigma is None:
        controller = hc.OnlineController(law, hc.OnlineOptions(limits=limits))
        controller.reset(0.0, q)
    else:
        # Figure 2's filter: N = sigma^2 I, Sigma(t0) = I, Q = I; the estimate starts on the path.
        # The digital law runs its own filter (the discrete game's), the emulated one the sampled
        # form of the paper's (docs/online.md).
        update = hc.MeasurementUpdate.discrete if law.kind() == "digital" else hc.MeasurementUpdate.sampled
        f = hc.OnlineFilter(N=sigma**2 * np.eye(3), Sigma0=np.eye(6), Q=np.eye(6), update=update)
        controller = hc.OnlineController(law, hc.OnlineOptions(filter=f, limits=limits))
        controller.reset(0.0, trajectory.q_d(0.0))

    def measure(x):
        return x.copy() if sigma is None else x[3:6] + sigma * rng.standard_normal(3)

    u = controller.held_command()

    def plant(t, x):
        return ship.f(t, x) + ship.G(t, x) @ u + ship.D(t, x) @ disturbance(t)

    per_sample = round(period / h)
    errors = []
    measured = measure(q)
    for k in range(round(tf / period)):
        t_k = k * period
        if not delayed:
            u, _ = controller.step(t_k, measure(q), t_k)
        elif k > 0:
            u, _ = controller.step(t_k, measured, t_k - period)  # last sample's measurement, now
        measured = measure(q)
        for i in range(per_sample):
            t = t_k + i * h
            if t >= tf / 2:
                errors.append(np.sum((q[3:5] - trajectory.q_d(t)[3:5]) ** 2))
            k1 = plant(t, q)
            k2 = plant(t + h / 2, q + h / 2 * k1)
            k3 = plant(t + h / 2, q + h / 2 * k2)
            k4 = plant(t + h, q + h * k3)
            q = q + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return float(np.sqrt(np.mean(errors)))


def main() -> None:
    trajectory, design = paper_design()
    print("RMS position error over [20, 40] s (continuous loop: 0.0479 m)")
    for period in (0.05, 0.2):
        emulated = hc.SampledLaw.emulated(design, period)
        digital = hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, period, np.eye(6), np.eye(6), 5.0))
        print(f"T = {period:.2f} s: emulated {run_loop(trajectory, emulated, period):.4f} m, "
              f"digital {run_loop(trajectory, digital, period):.4f} m, "
              f"emulated one sample late {run_loop(trajectory, emulated, period, delayed=True):.4f} m")
    emulated = hc.SampledLaw.emulated(design, 0.05)
    digital = hc.SampledLaw.digital(hc.solve_discrete_game(trajectory, 0.05, np.eye(6), np.eye(6), 5.0))
    print(f"output feedback, x, y, psi with sigma = 0.5 per sample, T = 0.05 s: "
          f"{run_loop(trajectory, emulated, 0.05, sigma=0.5):.4f} m, "
          f"one sample late {run_loop(trajectory, emulated, 0.05, delayed=True, sigma=0.5):.4f} m, "
          f"digital law with its discrete filter {run_loop(trajectory, digital, 0.05, sigma=0.5):.4f} m")


if __name__ == "__main__":
    main()
