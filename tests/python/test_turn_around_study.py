"""The paper's claim (i) as a study: studies/turn_around.toml maps, per law, the starts ahead of
the desired point from which the ship is turned around (the run's metric turned_around). The
backstepping law's threshold is known in closed form: its commanded velocity
dp_d/dt - k (p - p_d) points backwards from more than u_d / k = 1 / 0.5 = 2 m ahead. Every
shipped study file is read here too (its keys and report checked when read)."""

from __future__ import annotations

import pathlib

import numpy as np

from hinf_cpp.studies import load_study, run_study

STUDIES = pathlib.Path(__file__).resolve().parents[2] / "studies"


def test_every_shipped_study_reads():
    files = sorted(STUDIES.glob("*.toml"))
    assert len(files) >= 6
    for path in files:
        study = load_study(path)
        assert study.runs >= 1, path.name


def test_only_the_backstepping_law_turns_around_and_only_beyond_u_d_over_k():
    table = run_study(load_study(STUDIES / "turn_around.toml"), progress=False)
    assert (table["status"] == "completed").all()
    ahead = table["initial.q0[3]"].to_numpy()
    turned = table["turned_around"].to_numpy() == 1.0
    backstepping = (table["law"] == "backstepping").to_numpy()
    np.testing.assert_array_equal(turned[backstepping], ahead[backstepping] > 2.0)
    assert not turned[~backstepping].any()
    # A turn is a loop: beyond the threshold the heading error passes 2 pi; below it, and for
    # the other laws everywhere, it stays under 0.2 rad.
    excursion = table["heading_excursion"].to_numpy()
    assert np.all(excursion[backstepping & (ahead > 2.0)] > 2 * np.pi)
    assert np.all(excursion[~(backstepping & (ahead > 2.0))] < 0.2)
