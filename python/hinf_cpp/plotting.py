"""Figures of a run, drawn on matplotlib Figure objects (no display needed)."""

from __future__ import annotations

import pathlib

import numpy as np
from matplotlib.figure import Figure

from . import _core

__all__ = ["xy_figure", "save_figure"]


def _position_indices(result: _core.RunResult) -> tuple[int, int]:
    indices = result.trajectory.model.position_indices()
    if len(indices) != 2:
        raise ValueError(f"the model '{result.trajectory.model.name()}' has no planar position "
                         "(position_indices() must give two indices) to draw an x-y plot")
    return indices[0], indices[1]


def xy_figure(result: _core.RunResult, title: str | None = None) -> Figure:
    """The paper's x-y plot: desired path solid, actual path dashed, start points marked."""
    ix, iy = _position_indices(result)
    sim = result.simulation
    fig = Figure(figsize=(6.4, 5.2), layout="constrained")
    ax = fig.subplots()
    ax.plot(sim.q_d[:, ix], sim.q_d[:, iy], "-", color="black", lw=1.5, label="desired")
    ax.plot(sim.q[:, ix], sim.q[:, iy], "--", color="tab:blue", lw=1.5, label="actual")
    ax.plot(sim.q_d[0, ix], sim.q_d[0, iy], "o", color="black", ms=5, label="desired start")
    ax.plot(sim.q[0, ix], sim.q[0, iy], "s", color="tab:blue", ms=5, label="actual start")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(title if title is not None else
                 f"{result.scenario_name}: {result.controller}, gamma = {result.gamma:g}")
    return fig


def save_figure(fig: Figure, path: str | pathlib.Path) -> pathlib.Path:
    """Saves a figure (format from the suffix: .png, .pdf, .svg)."""
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=150)
    return path


def position_error(result: _core.RunResult) -> np.ndarray:
    """|p - p_d| on the output grid."""
    ix, iy = _position_indices(result)
    q_e = result.simulation.q_e
    return np.hypot(q_e[:, ix], q_e[:, iy])
