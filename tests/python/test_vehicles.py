"""The built-in vehicles (cpp/include/hinf/models/vehicles.hpp, docs/vehicles.md) through the Python API.

Against independent truth: the vehicles' equations written out here in NumPy (the textbook
forms of docs/vehicles.md), central differences of them, and the identities the library
promises (the error split, a zero-error start staying on the trajectory). Also: each shipped
vehicle scenario tracks, hinf-sim and hinf-cpp write the same results file, pickling, the
scenario-file round trip, and the messages of bad parameters.
"""

from __future__ import annotations

import json
import math
import pathlib
import pickle
import re
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc
from _support import EPS, ROUNDOFF, central_jacobian, numbers_close

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(sys.executable).parent
HINF_SIM, HINF_CPP = BIN / "hinf-sim", BIN / "hinf-cpp"

# The shipped scenario of each vehicle.
SCENARIOS = {"fossen_vessel_turn": hc.FossenVessel, "hovercraft_s_curve": hc.Hovercraft,
             "pvtol_climb": hc.PlanarVtol, "auv_s_curve": hc.Auv}

# ---- the equations of docs/vehicles.md, written out in NumPy ----


def fossen_rhs(p: hc.FossenVesselParameters):
    """M nu_dot + C(nu) nu + D nu = B_tau tau + w (C(nu) of Fossen's skew-symmetric form for a
    general symmetric M), eta_dot = R(psi) nu; q = [u, v, r, x, y, psi]."""
    M, D = np.asarray(p.M), np.asarray(p.D)

    def rhs(q, tau, w=np.zeros(3)):
        nu, psi = q[:3], q[5]
        a1, a2 = M[0] @ nu, M[1] @ nu
        C = np.array([[0.0, 0.0, -a2], [0.0, 0.0, a1], [a2, -a1, 0.0]])
        nu_dot = np.linalg.solve(M, np.array([tau[0], 0.0, tau[1]]) + w - C @ nu - D @ nu)
        c, s = math.cos(psi), math.sin(psi)
        return np.concatenate([nu_dot, [c * nu[0] - s * nu[1], s * nu[0] + c * nu[1], nu[2]]])
    return rhs


def hovercraft_rhs(p: hc.HovercraftParameters):
    """q = [x, y, psi, vx, vy, r], u = [F, T] per unit mass and inertia."""
    def rhs(q, u, w=np.zeros(3)):
        x, y, psi, vx, vy, r = q
        return np.array([vx, vy, r, u[0] * math.cos(psi) - p.d * vx + w[0],
                         u[0] * math.sin(psi) - p.d * vy + w[1], u[1] - p.d_r * r + w[2]])
    return rhs


def pvtol_rhs(p: hc.PlanarVtolParameters):
    """Hauser, Sastry and Meyer (1992): q = [x, y, theta, x_dot, y_dot, theta_dot]."""
    def rhs(q, u, w=np.zeros(3)):
        theta = q[2]
        c, s = math.cos(theta), math.sin(theta)
        return np.array([q[3], q[4], q[5], -u[0] * s + p.epsilon * u[1] * c + w[0],
                         u[0] * c + p.epsilon * u[1] * s - p.g + w[1], u[1] + w[2]])
    return rhs


def auv_rhs(p: hc.AuvParameters):
    """Diagonal masses, linear and quadratic drag, no sway thrust; q = [u, v, r, x, y, psi]."""
    def rhs(q, tau, w=np.zeros(3)):
        u, v, r, _, _, psi = q
        c, s = math.cos(psi), math.sin(psi)
        return np.array([
            (p.m22 * v * r - p.X_u * u - p.X_uu * abs(u) * u + tau[0] + w[0]) / p.m11,
            (-p.m11 * u * r - p.Y_v * v - p.Y_vv * abs(v) * v + w[1]) / p.m22,
            ((p.m11 - p.m22) * u * v - p.N_r * r - p.N_rr * abs(r) * r + tau[1] + w[2]) / p.m33,
            c * u - s * v, s * u + c * v, r])
    return rhs


def reference_rhs(model: hc.Model):
    """The NumPy right-hand side (q, u, w_process) -> dq/dt of a built-in vehicle."""
    for cls, make in ((hc.FossenVessel, fossen_rhs), (hc.Hovercraft, hovercraft_rhs),
                      (hc.PlanarVtol, pvtol_rhs), (hc.Auv, auv_rhs)):
        if isinstance(model, cls):
            return make(model.parameters())
    raise TypeError(type(model).__name__)


GENERAL_VESSEL = hc.FossenVesselParameters(
    M=np.array([[2.0, 0.1, -0.2], [0.1, 3.0, 0.4], [-0.2, 0.4, 0.7]]),
    D=np.array([[0.5, 0.05, 0.0], [-0.1, 0.8, 0.2], [0.02, -0.05, 0.3]]))
MODELS = {
    "fossen supply vessel": hc.FossenVessel(),
    "fossen general M": hc.FossenVessel(GENERAL_VESSEL),
    "hovercraft": hc.Hovercraft(),
    "hovercraft other": hc.Hovercraft(hc.HovercraftParameters(d=0.7, d_r=0.0)),
    "pvtol": hc.PlanarVtol(),
    "pvtol other": hc.PlanarVtol(hc.PlanarVtolParameters(g=9.81, epsilon=-0.4)),
    "auv sirene": hc.Auv(),
    "auv other": hc.Auv(hc.AuvParameters(10, 20, 3, 1, 2, 3, 4, 0.5, 0.25)),
}


def random_point(rng, model):
    """A state with components in [-2, 2] (angles over more than a full turn), an input and a
    process disturbance in [-2, 2] (scaled by 100 for the AUV, whose inputs are forces in N)."""
    scale = 100.0 if isinstance(model, hc.Auv) else 1.0
    return rng.uniform(-2.0, 2.0, 6), scale * rng.uniform(-2.0, 2.0, 2), scale * rng.uniform(-1.0, 1.0, 3)


@pytest.mark.parametrize("label", MODELS)
def test_right_hand_side_is_the_documented_equations(label):
    """f + G u + D w of the library against the NumPy equations: different evaluations of the
    same formulas, compared at round-off of their terms (the largest entry of M^-1 (8, the
    supply vessel's 1 / m33) times the forces). Each model at one point, which shows that its
    class and parameters reach the library; the Fossen vessel with a general M at many:
    tests/cpp/test_vehicles.cpp checks each vehicle's equations at 40 points, but those of a
    general M only through the power balance of its forces."""
    model = MODELS[label]
    rhs = reference_rhs(model)
    rng = np.random.default_rng(31)
    for _ in range(30 if label == "fossen general M" else 1):
        q, u, w = random_point(rng, model)
        t = float(rng.uniform(0.0, 50.0))
        w_full = np.concatenate([w, rng.uniform(-1.0, 1.0, 3)])  # noise channels move nothing
        library = model.f(t, q) + model.G(t, q) @ u + model.D(t, q) @ w_full
        expected = rhs(q, u, w)
        terms = 10.0 * (1.0 + np.max(np.abs(expected)) + np.max(np.abs(u)) + np.max(np.abs(w)))
        np.testing.assert_allclose(library, expected, rtol=0, atol=ROUNDOFF * terms)


@pytest.mark.parametrize("label", MODELS)
def test_error_split_identity(label):
    """A(q_e) q_e + alpha = f_e with f_e = f(q_d + q_e) + G(q_d + q_e) u_d - f(q_d) - G(q_d) u_d
    (the input's drift included: the hovercraft's and the VTOL's G depend on the angle), at
    round-off of the terms; A(0) = A_e = d/dq [f + G u_d] at q_d, alpha(0) = 0."""
    model = MODELS[label]
    rng = np.random.default_rng(47)
    for _ in range(30):
        q_d, u_d, _ = random_point(rng, model)
        q_e = rng.uniform(-2.0, 2.0, 6)
        t = float(rng.uniform(0.0, 50.0))
        A, alpha = model.error_split(t, q_d, u_d, q_e)
        actual = model.f(t, q_d + q_e) + model.G(t, q_d + q_e) @ u_d
        desired = model.f(t, q_d) + model.G(t, q_d) @ u_d
        scale = (1.0 + 6.0 * np.max(np.abs(A)) * np.max(np.abs(q_e)) + np.max(np.abs(alpha))
                 + np.max(np.abs(actual)) + np.max(np.abs(desired)))
        np.testing.assert_allclose(A @ q_e + alpha, actual - desired, rtol=0, atol=ROUNDOFF * scale)
        A0, alpha0 = model.error_split(t, q_d, u_d, np.zeros(6))
        A_e = model.linearize(t, q_d, u_d)
        np.testing.assert_allclose(A0, A_e, rtol=0, atol=ROUNDOFF * (1.0 + np.max(np.abs(A_e))))
        np.testing.assert_allclose(alpha0, 0.0, rtol=0, atol=ROUNDOFF * (1.0 + np.max(np.abs(desired))))


@pytest.fixture(scope="module")
def shipped():
    """{name: (scenario, RunResult)} of the shipped vehicle scenarios."""
    out = {}
    for name in SCENARIOS:
        scenario = hc.load_scenario(hc.scenario_path(name))
        out[name] = (scenario, hc.run_scenario(scenario))
    return out


@pytest.mark.parametrize("name", SCENARIOS)
def test_linearization_along_the_shipped_trajectory(name, shipped):
    """A_e(t) of the trajectory against central differences of the NumPy right-hand side
    f(q) + G(q) u_d(t) at q_d(t) (for the hovercraft and the VTOL this checks the part of G that
    depends on the angle). Central differences with h = 1e-6 max(1, |q_j|): round-off of two
    evaluations of F (entries <= |F|) over 2h, at most 1e3 eps |F| / h (2.2e-7 |F|); truncation
    h^2 |F'''| / 6 with |F'''| < 10^3 (F is quadratic in the velocities times sines and cosines
    of one angle, with |q| < 60 on these trajectories): below 2e-10. The AUV's |v| v has no
    third derivative at v = 0, where its trajectory starts: within h of 0 the difference quotient
    of c |v| v is off by up to c h (c <= Y_vv / m22 and the like)."""
    scenario, result = shipped[name]
    model = result.trajectory.model()
    assert isinstance(model, SCENARIOS[name])
    rhs = reference_rhs(model)
    kink = 0.0
    if isinstance(model, hc.Auv):
        p = model.parameters()
        kink = 1e-6 * max(p.X_uu / p.m11, p.Y_vv / p.m22, p.N_rr / p.m33)
    times = np.linspace(scenario.t0, scenario.tf, 21)
    A_e = result.trajectory.A_e(times)
    for k, t in enumerate(times):
        q_d, u_d = result.trajectory.q_d(t), result.trajectory.u_d(t)
        F = lambda q: rhs(q, u_d)  # noqa: E731
        J = central_jacobian(F, q_d)
        size = 1.0 + np.max(np.abs(F(q_d))) + np.max(np.abs(J))
        np.testing.assert_allclose(A_e[k], J, rtol=0, atol=1e3 * EPS * size / 1e-6 + 2e-10 + kink,
                                   err_msg=f"t = {t}")


@pytest.mark.parametrize("name", SCENARIOS)
def test_zero_error_start_stays_on_the_trajectory(name):
    """q0 = q_d0 and no disturbance: u = u_d and q(t) = q_d(t) up to the integrators' accuracy.
    The closed loop is integrated at rtol 1e-8, atol 1e-10 (the scenario's [solver]), the
    trajectory at rtol 1e-10: their difference is bounded by 1e3 (the global-error factor of
    test_properties.py) times rtol times the state's size, plus 1e3 atol."""
    scenario = hc.load_scenario(hc.scenario_path(name))
    scenario.initial_q0 = scenario.desired_q0
    scenario.disturbance = hc.VectorSignal.zeros(6)
    result = hc.run_scenario(scenario)
    assert result.simulation.status == hc.RunStatus.completed
    q, q_d = np.asarray(result.simulation.q), np.asarray(result.simulation.q_d)
    size = 1.0 + np.max(np.abs(q_d))
    assert np.max(np.abs(q - q_d)) < 1e3 * (scenario.solver.rtol * size + scenario.solver.atol)
    # The law's correction u - u_d = -K q_e is as small, times the gain.
    gain = max(np.max(np.abs(result.solution.gain(t))) for t in np.linspace(scenario.t0, scenario.tf, 11))
    u_error = np.max(np.abs(np.asarray(result.simulation.u) - np.asarray(result.simulation.u_d)))
    assert u_error < 6.0 * gain * 1e3 * (scenario.solver.rtol * size + scenario.solver.atol)


def gamma_star_of_comment(name: str) -> float:
    """The gamma* the scenario file's comment states ("# gamma* = 16.3 ...")."""
    text = (ROOT / "scenarios" / f"{name}.toml").read_text()
    return float(re.search(r"# gamma\* = ([0-9.]+)", text).group(1))


@pytest.mark.parametrize("name", SCENARIOS)
def test_shipped_scenario_tracks(name, shipped):
    """The shipped run tracks: the final position error is below 10 % of the initial one; the
    design's gamma is at least twice gamma* (and gamma* is the one the file states)."""
    scenario, result = shipped[name]
    assert result.simulation.status == hc.RunStatus.completed
    assert result.law == hc.Law.hinf and not result.output_feedback
    model = result.trajectory.model()
    position = list(model.position_indices())
    q_e = np.asarray(result.simulation.q_e())[:, position]
    initial, final = np.linalg.norm(q_e[0]), np.linalg.norm(q_e[-1])
    assert initial > 0.1
    assert final < 0.1 * initial
    # The metric is the same norm at the last output time.
    assert result.metrics.final_position_error == pytest.approx(final, rel=ROUNDOFF)
    gamma_star = hc.scenario_gamma_star(scenario).gamma_star
    assert scenario.gamma >= 2.0 * gamma_star
    assert gamma_star == pytest.approx(gamma_star_of_comment(name), rel=5e-3)  # printed to 3 digits


@pytest.fixture(scope="module")
def warm_python_cli():
    subprocess.run([sys.executable, "-c", "import hinf_cpp.cli"], capture_output=True, timeout=300)


@pytest.mark.skipif(not (HINF_SIM.exists() and HINF_CPP.exists()),
                    reason="hinf-sim / hinf-cpp are not installed next to this Python")
@pytest.mark.parametrize("name", SCENARIOS)
def test_both_programs_write_the_same_results(name, tmp_path, warm_python_cli):
    path = hc.scenario_path(name)
    runs = [[HINF_SIM, path, "--json", tmp_path / "sim.json", "--csv", tmp_path / "sim.csv"],
            [HINF_CPP, "run", path, "--json", tmp_path / "cpp.json", "--csv", tmp_path / "cpp.csv"]]
    for args in runs:
        done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=120)
        assert done.returncode == 0 and done.stderr == "", done.stderr
    sim, cpp = (json.loads((tmp_path / f"{p}.json").read_text()) for p in ("sim", "cpp"))
    numbers_close(sim, cpp)
    assert sim["model"] == {"name": SCENARIOS[name]().name(), "jacobian": "automatic differentiation",
                            "parameters": hc.load_scenario(path).model.named_parameters()}
    sim_csv, cpp_csv = (np.loadtxt(tmp_path / f"{p}.csv", delimiter=",", skiprows=1) for p in ("sim", "cpp"))
    np.testing.assert_array_equal(sim_csv, cpp_csv)  # the same run printed with 17 digits


@pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
def test_vehicles_command_writes_the_gallery(tmp_path, warm_python_cli):
    out = tmp_path / "gallery"
    done = subprocess.run([str(HINF_CPP), "vehicles", "--out", str(out)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    for name in SCENARIOS:
        assert (out / f"{name}_xy.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        results = json.loads((out / f"{name}.json").read_text())
        assert results["gamma_star"] is not None and results["gamma"] > results["gamma_star"]
        assert (out / f"{name}.csv").stat().st_size > 0
    assert (out / "vehicles_xy.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    table = (out / "metrics.md").read_text()
    assert all(hc.load_scenario(hc.scenario_path(name)).name in table for name in SCENARIOS)
    assert all(hc.load_scenario(hc.scenario_path(name)).name in done.stdout for name in SCENARIOS)


@pytest.mark.parametrize("label", MODELS)
def test_models_pickle_by_value(label):
    model = MODELS[label]
    copy = pickle.loads(pickle.dumps(model))
    assert type(copy) is type(model) and copy is not model
    assert copy.parameters() == model.parameters()
    rng = np.random.default_rng(3)
    for _ in range(5):
        q, u, _ = random_point(rng, model)
        np.testing.assert_array_equal(copy.f(0.0, q), model.f(0.0, q))
        np.testing.assert_array_equal(copy.dfdq(0.0, q), model.dfdq(0.0, q))
        np.testing.assert_array_equal(copy.G(0.0, q), model.G(0.0, q))
        np.testing.assert_array_equal(copy.dGudq(0.0, q, u), model.dGudq(0.0, q, u))
    parameters = model.parameters()
    assert pickle.loads(pickle.dumps(parameters)) == parameters


@pytest.mark.parametrize("name", SCENARIOS)
def test_scenario_file_round_trip(name, shipped):
    """The shipped file written back (every parameter spelt out) reads back to the same text
    and the same model; the scenario pickles as that text."""
    scenario, _ = shipped[name]
    text = hc._core.scenario_toml(scenario)
    again = hc._core.parse_scenario_toml(text, "written.toml")
    assert hc._core.scenario_toml(again) == text
    assert again.model.parameters() == scenario.model.parameters()
    assert hc._core.scenario_toml(pickle.loads(pickle.dumps(scenario))) == text


def test_scenario_file_round_trip_of_other_parameters():
    base = hc.load_scenario(hc.scenario_path("pvtol_climb"))
    for model in MODELS.values():
        base.model = model
        again = hc._core.parse_scenario_toml(hc._core.scenario_toml(base), "written.toml")
        assert type(again.model) is type(model) and again.model.parameters() == model.parameters()


def test_parameter_structs_and_presets():
    assert hc.FossenVesselParameters.supply_vessel() == hc.FossenVesselParameters()
    np.testing.assert_array_equal(hc.FossenVesselParameters().M,
                                  [[1.1274, 0.0, 0.0], [0.0, 1.8902, -0.0744], [0.0, -0.0744, 0.1278]])
    np.testing.assert_array_equal(hc.FossenVesselParameters().D,
                                  [[0.0358, 0.0, 0.0], [0.0, 0.1183, -0.0124], [0.0, -0.0041, 0.0308]])
    assert hc.AuvParameters.sirene() == hc.AuvParameters(215.0, 265.0, 80.0, 70.0, 100.0, 100.0, 200.0, 50.0, 100.0)
    assert hc.HovercraftParameters() == hc.HovercraftParameters(d=0.2, d_r=0.5)
    assert hc.PlanarVtolParameters() == hc.PlanarVtolParameters(g=1.0, epsilon=0.1)
    for name in ("FossenVessel", "Hovercraft", "PlanarVtol", "Auv", "FossenVesselParameters",
                 "HovercraftParameters", "PlanarVtolParameters", "AuvParameters"):
        assert name in hc.__all__


@pytest.mark.parametrize("make, words", [
    (lambda: hc.FossenVessel(hc.FossenVesselParameters(M=np.diag([1.0, 1.0, -1.0]))),
     ["mass matrix M must be positive definite"]),
    (lambda: hc.FossenVessel(hc.FossenVesselParameters(M=np.array([[1.0, 0, 0], [0, 1.0, 0.2], [0, 0, 1.0]]))),
     ["mass matrix M must be symmetric", "m23 = m32"]),
    (lambda: hc.FossenVessel(hc.FossenVesselParameters(M=np.eye(2))), ["mass matrix M", "(3, 3)"]),
    (lambda: hc.FossenVessel(hc.FossenVesselParameters(D=np.diag([0.1, -0.1, 0.1]))),
     ["damping matrix D", "(D + D')/2", "positive definite"]),
    (lambda: hc.Hovercraft(hc.HovercraftParameters(d=-0.1)), ["Hovercraft", "translational damping d", ">= 0"]),
    (lambda: hc.Hovercraft(hc.HovercraftParameters(d_r=math.nan)), ["rotational damping d_r"]),
    (lambda: hc.PlanarVtol(hc.PlanarVtolParameters(g=-9.81)), ["PlanarVtol", "gravity g"]),
    (lambda: hc.PlanarVtol(hc.PlanarVtolParameters(epsilon=math.inf)), ["epsilon", "finite"]),
    (lambda: hc.Auv(hc.AuvParameters(m22=0.0)), ["Auv", "sway mass m22", "> 0"]),
    (lambda: hc.Auv(hc.AuvParameters(N_rr=-1.0)), ["quadratic yaw drag N_rr", ">= 0"]),
])
def test_bad_parameters_are_clear_errors(make, words):
    with pytest.raises(ValueError) as error:
        make()
    for word in words:
        assert word in str(error.value)


PVTOL_TEXT = (ROOT / "scenarios" / "pvtol_climb.toml").read_text()


@pytest.mark.parametrize("model, words", [
    ('kind = "pvtol"\ng = 1.0\nepsilon = 0.1\nm_u = 0.5', ['[model] m_u', 'is a key of kind = "ship"']),
    ('kind = "pvtol"\nG = 1.0', ["unknown key 'G'", "known keys: kind, g, epsilon"]),
    ('kind = "fossen_vessel"\npreset = "tanker"', ['[model] preset', 'unknown preset "tanker"', '"supply_vessel"']),
    ('kind = "fossen_vessel"\nD = [[0.1, 0.0, 0.0], [0.0, -0.1, 0.0], [0.0, 0.0, 0.1]]',
     ["[model] FossenVessel: the damping matrix D"]),
    ('kind = "auv"\nm11 = "heavy"', ["[model] m11", "expected a number"]),
    ('kind = "hovercraft"\nd = -1.0', ["[model] Hovercraft", "damping d"]),
    ('kind = "zeppelin"', ['unknown model kind "zeppelin"', '"pvtol"']),
])
def test_bad_model_sections_name_the_key(model, words, tmp_path):
    text = re.sub(r'\[model\]\n(.*?)\n\n', lambda m: f"[model]\n{model}\n\n", PVTOL_TEXT, count=1, flags=re.S)
    assert model in text
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(ValueError) as error:
        hc.load_scenario(path)
    message = str(error.value)
    assert message.startswith(f"{path}: ")
    for word in words:
        assert word in message, message
