"""FleetModel: k uncoupled copies of a model, block-diagonal. Checked against the member model
evaluated vehicle by vehicle, and the fleet's GRDE against the single vehicle's (the Riccati
equation of a block-diagonal system with block-diagonal weights has the block-diagonal
solution, so the fleet of 2 ships, n = 12, solved on the Lyapunov Newton path, must give
blockdiag(Z_ship, Z_ship) of the 6-state solve)."""
import pickle

import numpy as np
import pytest

import hinf_cpp as hc
from _support import PAPER_Q_D0


def stacked(x, count):
    return np.concatenate([np.asarray(x, dtype=float)] * count)


def test_fleet_is_the_member_vehicle_by_vehicle(ship):
    fleet = hc.FleetModel(ship, 3)
    assert (fleet.n(), fleet.m(), fleet.nw()) == (18, 6, 18)
    assert fleet.name() == "fleet of 3 ship"
    rng = np.random.default_rng(7)
    q = rng.standard_normal(18)
    f = fleet.f(0.5, q)
    J = fleet.dfdq(0.5, q)
    for i in range(3):
        block = slice(6 * i, 6 * (i + 1))
        # The same member code on the same numbers: equal.
        assert np.array_equal(f[block], ship.f(0.5, q[block]))
        assert np.array_equal(J[block, block], ship.dfdq(0.5, q[block]))
        off = np.ones(18, dtype=bool)
        off[block] = False
        assert not np.any(J[block][:, off])
    assert np.array_equal(fleet.G(0.0, np.zeros(fleet.n())), np.kron(np.eye(3), ship.G(0.0, np.zeros(ship.n()))))
    assert np.array_equal(fleet.D(0.0, np.zeros(fleet.n())), np.kron(np.eye(3), ship.D(0.0, np.zeros(ship.n()))))
    assert np.array_equal(fleet.C(0.0), np.kron(np.eye(3), ship.C(0.0)))
    assert fleet.noise_channels() == [3, 4, 5, 9, 10, 11, 15, 16, 17]
    assert fleet.position_indices() == [3, 4, 9, 10, 15, 16]
    assert fleet.heading_index() == -1
    assert fleet.state_names()[:7] == [name + "_1" for name in ship.state_names()] + [ship.state_names()[0] + "_2"]
    q_d = rng.standard_normal(18)
    assert fleet.remainder_bound(0.0, q_d, 1.0) == max(
        ship.remainder_bound(0.0, q_d[6 * i:6 * (i + 1)], 1.0) for i in range(3))


def test_fleet_grde_is_block_diagonal(ship, paper_u_d):
    count = 2
    single = hc.Trajectory(ship, PAPER_Q_D0, paper_u_d, 0.0, 40.0)
    fleet = hc.Trajectory(hc.FleetModel(ship, count), stacked(PAPER_Q_D0, count), paper_u_d * count, 0.0, 40.0)
    options = hc.SolverOptions("bdf", rtol=1e-10, atol=1e-12)
    Z1 = hc.solve_grde(single, np.eye(6), np.eye(6), 5.0, options)
    Zk = hc.solve_grde(fleet, np.eye(12), np.eye(12), 5.0, options)
    # Detected from the fleet and the block-diagonal weights: one GRDE per ship.
    assert Zk.stats().method == "bdf (Lyapunov Newton) in 2 uncoupled blocks"
    assert Z1.stats().method == "bdf (dense Newton)"
    for t in np.linspace(0.0, 40.0, 41):
        expected = np.kron(np.eye(count), Z1.Z(t))
        # Two solves at rtol 1e-10 of a solution of size |Z| ~ 5: global errors of a few 1e-9
        # each (the solve is stable backward in time); 1e-7 leaves a factor 20.
        assert np.max(np.abs(Zk.Z(t) - expected)) < 1e-7 * max(1.0, np.max(np.abs(expected))), t


def test_fleet_solution_is_stored_by_ship_and_pickles(ship, paper_u_d):
    count = 3
    fleet = hc.Trajectory(hc.FleetModel(ship, count), stacked(PAPER_Q_D0, count), paper_u_d * count, 0.0, 40.0)
    Z = hc.solve_grde(fleet, np.eye(18), np.eye(18), 5.0)
    assert Z.blocks() == [6, 6, 6] and Z.dense().dim() == 3 * 21  # three packed 6 x 6 triangles
    copy = pickle.loads(pickle.dumps(Z))
    assert copy.blocks() == Z.blocks()
    times = np.linspace(0.0, 40.0, 101)
    np.testing.assert_array_equal(copy.Z(times), Z.Z(times))
    state = list(Z.__getstate__())
    state[4] = [6, 12]  # the same states, but another storage than the dense output's
    broken = hc.RiccatiSolution.__new__(hc.RiccatiSolution)
    with pytest.raises(ValueError, match="needs 99 components, got 63"):
        broken.__setstate__(tuple(state))
    state[4] = [6, 6]
    with pytest.raises(ValueError, match="n = 18 cannot be stored in blocks of 12 states"):
        broken.__setstate__(tuple(state))


def test_fleet_bad_input_and_pickle(ship):
    with pytest.raises(ValueError, match="at least 1"):
        hc.FleetModel(ship, 0)
    with pytest.raises(ValueError, match="exceed"):
        hc.FleetModel(ship, 5000)
    copy = pickle.loads(pickle.dumps(hc.FleetModel(ship, 4)))
    assert copy.count() == 4 and copy.n() == 24 and copy.member().parameters() == ship.parameters()
