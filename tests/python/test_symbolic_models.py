"""Models written with CasADi symbols (hinf_cpp.models.symbolic), compiled to C and evaluated in C++.

The paper's ship, its statement (hinf_cpp.models.builtin.ship) compiled at run time into a
cache, against the built-in ShipModel that compiles in the C code of the same statement, on the
Figure 1 and Figure 2 runs (the run-time route: code generation, compiler, loader, cache); Jacobians from automatic differentiation against central
differences; the scenario-file route (kind = "casadi") through hinf-sim and hinf-cpp; the
cache; and bad models, which are errors naming the problem when the model is built.
"""

from __future__ import annotations

import json
import pathlib
import pickle
import subprocess
import sys

import numpy as np
import pytest

import hinf_cpp as hc

ca = pytest.importorskip("casadi")
from hinf_cpp.models import builtin  # noqa: E402
from hinf_cpp.models.symbolic import SymbolicModel  # noqa: E402

BIN = pathlib.Path(sys.executable).parent


@pytest.fixture(autouse=True)
def trusted_code(monkeypatch):
    """The scenarios here name models that are code, written by these tests: trusted
    (docs/trust.md; test_trust.py checks the refusal without it). Subprocesses inherit it."""
    monkeypatch.setenv("HINF_TRUST_CODE", "1")



@pytest.fixture(scope="module")
def cache_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("casadi-cache")


@pytest.fixture(scope="module")
def ship_symbolic():
    return builtin.ship()


@pytest.fixture(scope="module")
def ship_generated(ship_symbolic, cache_dir):
    return ship_symbolic.compile(cache_dir=cache_dir)


def with_model(scenario, model):
    copy = pickle.loads(pickle.dumps(scenario))
    copy.model = model
    return copy


def test_generated_ship_functions_equal_the_built_in_ones(ship_generated):
    """f, G, D, C and the error split at random states; the generated code may order the
    floating-point operations differently, so agreement is to round-off of the terms
    (products of up to three O(1) factors: 1e-14 of the scale)."""
    ship = hc.ShipModel()
    rng = np.random.default_rng(11)
    assert ship_generated.n() == 6 and ship_generated.m() == 2 and ship_generated.nw() == 6
    assert ship_generated.state_names() == ship.state_names()
    assert ship_generated.position_indices() == [3, 4] and ship_generated.heading_index() == 5
    assert ship_generated.noise_channels() == ship.noise_channels()
    assert ship_generated.constant_input_matrices() and not ship_generated.state_dependent_inputs()
    assert ship_generated.jacobian_method() == "automatic differentiation"
    for _ in range(20):
        q, q_e, u_d = 2 * rng.normal(size=6), rng.normal(size=6), rng.normal(size=2)
        scale = 1 + np.abs(q).max() ** 3
        np.testing.assert_allclose(ship_generated.f(0.3, q), ship.f(0.3, q), rtol=0, atol=1e-14 * scale)
        np.testing.assert_allclose(ship_generated.dfdq(0.3, q), ship.dfdq(0.3, q), rtol=0, atol=1e-14 * scale)
        A, alpha = ship_generated.error_split(0.3, q, u_d, q_e)
        A_ref, alpha_ref = ship.error_split(0.3, q, u_d, q_e)
        np.testing.assert_allclose(A, A_ref, rtol=0, atol=1e-14 * scale)
        np.testing.assert_allclose(alpha, alpha_ref, rtol=0, atol=1e-13 * scale)
    zeros = np.zeros(6)
    np.testing.assert_array_equal(ship_generated.G(0.0, zeros), ship.G(0.0, zeros))
    np.testing.assert_array_equal(ship_generated.D(0.0, zeros), ship.D(0.0, zeros))
    np.testing.assert_array_equal(ship_generated.C(0.0), ship.C(0.0))


def test_automatic_differentiation_against_central_differences(ship_generated):
    """df/dq of the generated code against central differences of its own f (step 1e-6:
    truncation ~1e-12, round-off ~1e-10 for O(1) values)."""
    rng = np.random.default_rng(12)
    h = 1e-6
    for _ in range(10):
        q = rng.normal(size=6)
        J = np.column_stack([(ship_generated.f(0.0, q + h * e) - ship_generated.f(0.0, q - h * e)) / (2 * h)
                             for e in np.eye(6)])
        np.testing.assert_allclose(ship_generated.dfdq(0.0, q), J, rtol=0, atol=1e-8)


@pytest.mark.parametrize("name", ["paper_fig1", "paper_fig2"])
def test_symbolic_ship_reproduces_the_built_in_ship(name, ship_generated):
    """The Figure 1 (state feedback) and Figure 2 (output feedback) runs with the symbolic ship
    and with ShipModel: the same integrations on functions equal to round-off, so the results
    agree to the integrators' tolerance (rtol 1e-8 of the scenario's solver; 1e-6 of the
    scale leaves a margin of 100 for step-size decisions that round-off may flip)."""
    scenario = hc.load_scenario(hc.scenario_path(name))
    reference = hc.run_scenario(scenario)
    result = hc.run_scenario(with_model(scenario, ship_generated))
    a, b = json.loads(hc._core.results_json(reference)), json.loads(hc._core.results_json(result))
    # The symbolic ship's parameters have the built-in ship's names and values.
    assert b["model"] == {"name": "ship", "jacobian": "automatic differentiation",
                          "parameters": a["model"]["parameters"]}
    assert a["status"] == b["status"] == "completed"
    for key, value in a["metrics"].items():
        if value is None:
            assert b["metrics"][key] is None, key
        else:
            assert b["metrics"][key] == pytest.approx(value, rel=1e-6, abs=1e-9), key
    np.testing.assert_allclose(result.simulation.q, reference.simulation.q, rtol=0,
                               atol=1e-6 * np.abs(reference.simulation.q).max())
    np.testing.assert_allclose(np.asarray(b["Z0"]), np.asarray(a["Z0"]), rtol=1e-6)


# ---- scenario files: hinf-sim and hinf-cpp ----

@pytest.fixture(scope="module")
def exported_ship(ship_symbolic, cache_dir, tmp_path_factory):
    folder = tmp_path_factory.mktemp("exported") / "ship"
    return ship_symbolic.export(folder, cache_dir=cache_dir)


def casadi_scenario_text(model_file: str, extra: str = "") -> str:
    text = hc.scenario_path("paper_fig1").read_text()
    start = text.index("[model]")
    end = text.index("\n[", start + 1)
    return (text[:start] + f'[model]\nkind = "casadi"\nfile = "{model_file}"\n{extra}' + text[end:])


@pytest.mark.skipif(not (BIN / "hinf-sim").exists(), reason="hinf-sim is not installed next to this Python")
def test_hinf_sim_and_hinf_cpp_run_the_same_casadi_scenario(exported_ship, tmp_path):
    """The scenario names model.json relative to its own folder; both programs write the same
    results file (the same library code on the same file: equal up to printed digits)."""
    folder = exported_ship.parent.parent
    path = folder / "ship_casadi.toml"
    path.write_text(casadi_scenario_text("ship/model.json"))
    outputs = {}
    for program, args in (("sim", [BIN / "hinf-sim", path]), ("cpp", [BIN / "hinf-cpp", "run", path])):
        out = tmp_path / f"{program}.json"
        result = subprocess.run([str(a) for a in args] + ["--json", str(out)], capture_output=True, text=True,
                                timeout=300, cwd=tmp_path)
        assert result.returncode == 0, result.stderr
        outputs[program] = json.loads(out.read_text())
    a, b = outputs["sim"], outputs["cpp"]
    for key in ("metrics", "Z0", "model", "status"):
        assert json.dumps(a[key]) == json.dumps(b[key]), key


def test_scenario_parameters_and_round_trip(exported_ship, tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(casadi_scenario_text(str(exported_ship), "[model.parameters]\nd_u = 1.5\n"))
    scenario = hc.load_scenario(path)
    assert scenario.model.parameters()["d_u"] == 1.5 and scenario.model.parameters()["m_v"] == -2.0
    q = np.array([1.0, 0.2, 0.1, 0.0, 0.0, 0.3])
    assert scenario.model.f(0.0, q)[0] == pytest.approx(0.5 * 0.2 * 0.1 - 1.5 * 1.0, rel=1e-15)
    again = hc._core.parse_scenario_toml(hc._core.scenario_toml(scenario), "round trip", True)
    assert again.model.parameters() == scenario.model.parameters()
    copy = pickle.loads(pickle.dumps(scenario.model))
    np.testing.assert_array_equal(copy.f(0.0, q), scenario.model.f(0.0, q))


@pytest.mark.parametrize("extra, message", [
    ("[model.parameters]\nnot_there = 1.0\n", "has no parameter 'not_there'"),
    ("[model.parameters]\nd_u = \"x\"\n", "expected a number"),
])
def test_bad_scenario_parameters(exported_ship, tmp_path, extra, message):
    path = tmp_path / "s.toml"
    path.write_text(casadi_scenario_text(str(exported_ship), extra))
    with pytest.raises(ValueError, match=message):
        hc.load_scenario(path)


def test_missing_or_foreign_model_file(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(casadi_scenario_text("nowhere/model.json"))
    with pytest.raises(ValueError, match=r"model.json' cannot be read: no such file"):
        hc.load_scenario(path)
    (tmp_path / "other.json").write_text('{"format": "something else"}')
    path.write_text(casadi_scenario_text("other.json"))
    with pytest.raises(ValueError, match="is not a model description"):
        hc.load_scenario(path)


# ---- the cache ----

def test_second_build_is_a_cache_hit(ship_symbolic, cache_dir):
    first = ship_symbolic.build(cache_dir)
    again = builtin.ship().build(cache_dir)
    assert again.cache_hit and again.metadata_path == first.metadata_path
    assert again.compile_seconds == 0  # the C code is generated again to find its hash, not compiled


# ---- a state-dependent symbolic model ----

def test_state_dependent_symbolic_model(cache_dir):
    """A hovercraft (thrust along the body axis in inertial coordinates): G depends on psi, so
    d(G u)/dq is nonzero; checked against the closed form u_1 [-sin psi, cos psi]."""
    q = ca.SX.sym("q", 6)
    d = ca.SX.sym("d")
    G = ca.SX.zeros(6, 2)
    G[3, 0], G[4, 0], G[5, 1] = ca.cos(q[2]), ca.sin(q[2]), 1
    model = SymbolicModel("hover", state=q, inputs=2, f=ca.vertcat(q[3], q[4], q[5], -d * q[3], -d * q[4], -d * q[5]),
                          G=G, D=ca.vertcat(ca.DM.zeros(3, 3), ca.DM.eye(3)), parameters=d,
                          parameter_values={"d": 0.5}, position_indices=[0, 1], heading_index=2).compile(cache_dir=cache_dir)
    assert model.state_dependent_inputs() and not model.constant_input_matrices()
    qv, u = np.array([0.1, 0.2, 0.7, 1.0, 0.0, 0.1]), np.array([2.0, -1.0])
    expected = np.zeros((6, 6))
    expected[3, 2], expected[4, 2] = -2.0 * np.sin(0.7), 2.0 * np.cos(0.7)
    np.testing.assert_allclose(model.dGudq(0.0, qv, u), expected, rtol=0, atol=1e-15)
    tr = hc.Trajectory(model, [0.0, 0.0, 0.0, 1.0, 0.0, 0.0], [1.0, 0.2], 0.0, 5.0)
    A = tr.A_e(2.0)
    assert A[3, 2] == pytest.approx(-np.sin(tr.q_d(2.0)[2]), abs=1e-14)


# ---- bad models: clear errors where the model is built ----

def bad_model(**change):
    q = change.get("state", ca.SX.sym("q", 2))
    args = dict(state=q, inputs=1, f=ca.vertcat(q[1], -q[0]), G=ca.DM([[0], [1]]), D=ca.DM([[0], [1]]))
    args.update(change)
    return SymbolicModel("bad", **args)


@pytest.mark.parametrize("change, message", [
    (dict(f=ca.DM([1, 2, 3])), r"f has shape \(3, 1\), expected \(2, 1\)"),
    (dict(G=ca.DM([[0, 1], [1, 0]])), r"G has shape \(2, 2\), expected \(2, 1\) \(n x m = 2 x 1"),
    (dict(D=ca.DM([[0], [1], [2]])), r"D has shape \(3, 1\), expected 2 rows"),
    (dict(inputs=0), "inputs must be the number of inputs m >= 1"),
    (dict(position_indices=[0, 5]), r"position_indices\(\) = \[0, 5\] holds 5, which is not a state index"),
    (dict(heading_index=2), r"heading_index\(\) must be -1 \(no heading\) or a state index \(0 to 1\), got 2"),
    (dict(state_names=["a"]), r"state_names\(\) has 1 names, expected one per state"),
    (dict(f=ca.vertcat(ca.SX.sym("q", 2)[1], 0)), "f may only depend on t, q and the parameters"),
])
def test_bad_models_are_errors_at_construction(change, message):
    with pytest.raises(ValueError, match=message):
        bad_model(**change)


def test_an_expression_that_is_not_finite_is_an_error_at_construction():
    q = ca.SX.sym("q", 2)
    with pytest.raises(ValueError, match=r"f is not finite at the nominal state q = \[-1.0, 0.0\]"):
        bad_model(state=q, f=ca.vertcat(ca.sqrt(q[0]), q[1]), nominal_state=[-1.0, 0.0])
    with pytest.raises(ValueError, match=r"G is not finite at the nominal state q = \[0.0, 0.0\]"):
        bad_model(state=q, G=ca.vertcat(0, 1 / q[0]))


def test_unknown_and_missing_parameters_are_errors():
    q = ca.SX.sym("q", 2)
    k = ca.SX.sym("k")
    with pytest.raises(ValueError, match=r"missing: \['k'\]"):
        bad_model(state=q, f=ca.vertcat(q[1], -k * q[0]), parameters=k, parameter_values={})
    with pytest.raises(ValueError, match=r"unknown: \['j'\]"):
        bad_model(state=q, f=ca.vertcat(q[1], -k * q[0]), parameters=k, parameter_values={"k": 1.0, "j": 2.0})


def test_a_wrong_error_split_is_refused(cache_dir):
    q = ca.SX.sym("q", 2)
    model = bad_model(state=q, f=ca.vertcat(q[1], -ca.sin(q[0])), G=ca.DM([[0], [1]]),
                      error_split=lambda q_d, u_d, q_e: (ca.SX.zeros(2, 2), ca.SX.zeros(2, 1)))
    with pytest.raises(ValueError, match="error_split is not a decomposition of the error dynamics"):
        model.compile(cache_dir=cache_dir)


# ---- [model] kind = "python": Python-only ----

PYTHON_MODELS = '''
import casadi as ca
import numpy as np
import hinf_cpp as hc
from hinf_cpp.models.symbolic import SymbolicModel


class Integrator(hc.Model):
    """dp/dt = v, dv/dt = u + w (positions in p)."""
    def n(self): return 2
    def m(self): return 1
    def nw(self): return 1
    def f(self, t, q): return np.array([q[1], 0.0])
    def G(self, t, q): return np.array([[0.0], [1.0]])
    def D(self, t, q): return np.array([[0.0], [1.0]])
    def position_indices(self): return [0]


def subclass():
    return Integrator()


def symbolic():
    q = ca.SX.sym("q", 2)
    return SymbolicModel("integrator", state=q, inputs=1, f=ca.vertcat(q[1], 0), G=ca.DM([[0], [1]]),
                         D=ca.DM([[0], [1]]), position_indices=[0])


def not_a_model():
    return 42
'''

INTEGRATOR_SCENARIO = """
[model]
kind = "python"
callable = "{callable}"

[horizon]
tf = 10.0

[desired]
q0 = [0.0, 1.0]
u1 = 0.0

[initial]
q0 = [1.0, 1.0]

[controller]
gamma = 5.0
"""


@pytest.mark.parametrize("factory, model_class", [("subclass", "Model"), ("symbolic", "GeneratedModel")])
def test_python_kind_in_hinf_cpp(tmp_path, factory, model_class, monkeypatch):
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "cache"))
    (tmp_path / "my_models.py").write_text(PYTHON_MODELS)
    path = tmp_path / "s.toml"
    path.write_text(INTEGRATOR_SCENARIO.format(callable=f"my_models.py:{factory}"))
    scenario = hc.load_scenario(path)
    assert type(scenario.model).__name__ in ("Integrator", model_class)
    result = hc.run_scenario(scenario)
    assert result.metrics.final_position_error < 0.1  # from 1 m: the loop converges
    out = tmp_path / "cpp.json"
    run = subprocess.run([str(BIN / "hinf-cpp"), "run", str(path), "--json", str(out)], capture_output=True,
                         text=True, timeout=300, cwd=tmp_path)
    assert run.returncode == 0, run.stderr


@pytest.mark.skipif(not (BIN / "hinf-sim").exists(), reason="hinf-sim is not installed next to this Python")
def test_python_kind_is_refused_by_hinf_sim(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(INTEGRATOR_SCENARIO.format(callable="my_models.py:subclass"))
    run = subprocess.run([str(BIN / "hinf-sim"), str(path)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2
    assert len(run.stderr.splitlines()) == 1 and "run this scenario with hinf-cpp" in run.stderr


@pytest.mark.parametrize("callable_, message", [
    ("my_models.py:not_a_model", "returned int, not an hc.Model or a SymbolicModel"),
    ("my_models.py:absent", "has no callable 'absent'"),
    ("missing.py:f", "no Python file"),
    ("no_such_module_anywhere:f", "cannot import no_such_module_anywhere"),
    ("nocolon", "name it as MODULE:CALLABLE or FILE.py:CALLABLE"),
])
def test_python_kind_errors(tmp_path, callable_, message):
    (tmp_path / "my_models.py").write_text(PYTHON_MODELS)
    path = tmp_path / "s.toml"
    path.write_text(INTEGRATOR_SCENARIO.format(callable=callable_))
    with pytest.raises(ValueError, match=message):
        hc.load_scenario(path)
