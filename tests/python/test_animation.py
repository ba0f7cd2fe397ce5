"""Animations of a run (hinf_cpp.output.animation, `hinf-cpp animate`): the GIF read back with
Pillow, frame by frame, and its last frame compared with the run's final state.

The vessel is the only element drawn in its colour (VESSEL_RGB), a filled hull whose area
centroid is the vehicle's position and whose bow (its farthest point from that centroid) points
along the heading; so the centroid of the pixels of that colour in the last frame, mapped back,
is the run's final position, and the direction to the farthest of them its final heading.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image, ImageSequence

import hinf_cpp as hc
from hinf_cpp.output.animation import VESSEL_RGB, animate_run

HINF_CPP = pathlib.Path(sys.executable).parent / "hinf-cpp"
needs_cli = pytest.mark.skipif(not HINF_CPP.exists(), reason="hinf-cpp is not installed next to this Python")
GHOST_RGB = (90, 90, 90)


@pytest.fixture(scope="module")
def fig1():
    return hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))


def frames_rgb(path: pathlib.Path) -> list[np.ndarray]:
    with Image.open(path) as image:
        assert image.format == "GIF"
        return [np.asarray(frame.convert("RGB")) for frame in ImageSequence.Iterator(image)]


def vessel_pixels(rgb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(columns, rows) of the pixel centres (index + 0.5: Pillow's pixel i covers [i, i + 1)) of
    the vessel's colour."""
    rows, columns = np.nonzero(np.all(rgb == VESSEL_RGB, axis=2))
    return columns + 0.5, rows + 0.5


@pytest.mark.parametrize("marine", [False, True])
def test_last_frame_shows_the_vessel_at_the_final_state(tmp_path, fig1, marine):
    animation = animate_run(fig1, tmp_path / "fig1.gif", frames=25, fps=20, marine=marine)
    frames = frames_rgb(animation.path)
    assert len(frames) == animation.frames == 25
    np.testing.assert_array_equal(animation.times, np.linspace(0.0, 40.0, 25))
    pixel_map = animation.pixel_map
    assert frames[-1].shape == (pixel_map.height, pixel_map.width, 3)
    q = fig1.simulation.q[-1]
    columns, rows = vessel_pixels(frames[-1])
    assert columns.size > 150   # a hull at least 14 pixels long, filled
    centroid = np.array([columns.mean(), rows.mean()])
    expected = np.array(pixel_map.to_pixel(q[3], q[4]))
    # The filled polygon's pixels against its exact area centroid: each edge is rasterized to
    # within half a pixel, so the centroid moves by less than one; 1.5 px leaves a margin.
    assert np.linalg.norm(centroid - expected) < 1.5, (centroid, expected)
    # The bow: the farthest vessel pixel from the centroid, along the heading within 10 degrees
    # (a bow about 17 pixels out, its pixel's direction within atan(1/17) = 3.4 degrees, plus
    # the centroid's error).
    far = np.argmax(np.hypot(columns - centroid[0], rows - centroid[1]))
    bow = np.array([columns[far] - centroid[0], rows[far] - centroid[1]])
    heading = np.array(pixel_map.direction(q[5]))
    angle = math.degrees(math.acos(np.clip(bow @ heading / np.linalg.norm(bow), -1.0, 1.0)))
    assert angle < 10.0, angle
    # The world-to-pixel map by its definition: x right and y up, or (marine) y right and x up,
    # one scale for both; every point of both paths inside the frame.
    x, y = 3.0, -2.0
    h, v = (y, x) if marine else (x, y)
    assert pixel_map.to_pixel(x, y) == pytest.approx((pixel_map.origin[0] + pixel_map.scale * h,
                                                      pixel_map.origin[1] - pixel_map.scale * v), abs=1e-9)
    for states in (fig1.simulation.q, fig1.simulation.q_d):
        px, py = pixel_map.to_pixel(states[:, 3], states[:, 4])
        assert px.min() > 0 and px.max() < pixel_map.width and py.min() > 0 and py.max() < pixel_map.height


def test_first_frame_shows_the_start_and_the_ghost_where_they_differ(tmp_path):
    """Over 3 s from 1.41 m off the path the vessel and the desired position (ghost outline) are
    apart: the ghost's pixels surround the desired final position, the vessel's first-frame
    centroid is the initial position."""
    scenario = hc.load_scenario(hc.scenario_path("paper_fig1"))
    scenario.tf = 3.0
    result = hc.run_scenario(scenario)
    animation = animate_run(result, tmp_path / "short.gif", frames=10)
    frames = frames_rgb(animation.path)
    pixel_map = animation.pixel_map
    columns, rows = vessel_pixels(frames[0])
    start = np.array(pixel_map.to_pixel(*result.simulation.q[0, 3:5]))
    assert np.linalg.norm([columns.mean() - start[0], rows.mean() - start[1]]) < 1.5
    ghost_rows, ghost_columns = np.nonzero(np.all(frames[-1] == GHOST_RGB, axis=2))
    desired = np.array(pixel_map.to_pixel(*result.simulation.q_d[-1, 3:5]))
    vessel = np.array(pixel_map.to_pixel(*result.simulation.q[-1, 3:5]))
    assert np.linalg.norm(desired - vessel) > 60.0   # far apart on the frame
    distances = np.hypot(ghost_columns + 0.5 - desired[0], ghost_rows + 0.5 - desired[1])
    assert ghost_columns.size > 20 and distances.max() < 0.6 * max(14.0, 0.06 * pixel_map.width)


def test_frame_count_rate_and_every_frame_kept(tmp_path, fig1):
    animation = animate_run(fig1, tmp_path / "two.gif", frames=2, fps=12.5, width=320)
    with Image.open(animation.path) as image:
        assert image.n_frames == 2 and image.size[0] == 320
        assert image.info["duration"] == 80   # 1000 / 12.5 ms
    # Many frames close in time still differ (the time printed on each): none is merged away.
    many = animate_run(fig1, tmp_path / "many.gif", frames=300, fps=50)
    assert len(frames_rgb(many.path)) == 300


@pytest.mark.parametrize("options, message", [
    ({"frames": 1}, "frames must be an integer in [2, 2000], got 1"),
    ({"frames": 2001}, "frames must be"),
    ({"frames": 10.0}, "frames must be"),
    ({"frames": True}, "frames must be"),
    ({"fps": 0}, "fps must be a number in (0, 50]"),
    ({"fps": 51}, "fps must be"),
    ({"fps": float("nan")}, "fps must be"),
    ({"width": 100}, "width must be an integer in [160, 4096]"),
])
def test_bad_options_are_rejected_by_name(tmp_path, fig1, options, message):
    with pytest.raises(ValueError) as error:
        animate_run(fig1, tmp_path / "bad.gif", **options)
    assert message in str(error.value)
    assert not (tmp_path / "bad.gif").exists()


def test_bad_paths_and_models(tmp_path, fig1, monkeypatch):
    with pytest.raises(ValueError, match=r"must end in \.gif or \.mp4"):
        animate_run(fig1, tmp_path / "run.avi")
    monkeypatch.setenv("PATH", str(tmp_path))   # no ffmpeg here
    with pytest.raises(ValueError, match="MP4 needs ffmpeg on PATH"):
        animate_run(fig1, tmp_path / "run.mp4")
    monkeypatch.undo()
    s = hc.Scenario()
    s.model = hc.LinearModel(np.array([[-1.0]]), np.array([[1.0]]), np.array([[1.0]]))
    s.tf = 1.0
    s.desired_q0 = np.zeros(1)
    s.desired_u = [0.0]
    s.initial_q0 = np.array([0.1])
    s.gamma = 5.0
    with pytest.raises(ValueError, match="planar position and a heading"):
        animate_run(hc.run_scenario(s), tmp_path / "linear.gif")


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not on PATH")
def test_mp4_with_ffmpeg(tmp_path, fig1):
    animation = animate_run(fig1, tmp_path / "fig1.mp4", frames=20)
    data = animation.path.read_bytes()
    assert data[4:8] == b"ftyp" and len(data) > 1000


FAKE_FFMPEG = """#!{python}
# Stands in for ffmpeg: records its arguments and the bytes it was given, writes its output file.
import json, sys
data = sys.stdin.buffer.read()
json.dump({{"args": sys.argv[1:], "bytes": len(data)}}, open({log!r}, "w"))
if {fail}:
    sys.stderr.write("Unknown encoder 'libx264'\\n")
    sys.exit(1)
open(sys.argv[-1], "wb").write(b"....ftypisom" + data[:100])
"""


@pytest.mark.parametrize("fail", [False, True])
def test_mp4_goes_through_ffmpeg_on_path(tmp_path, fig1, monkeypatch, fail):
    """A stand-in ffmpeg on PATH: it gets the frames as raw RGB (width x height x 3 bytes each,
    the size and rate on its command line) and its output is renamed into place; when it fails,
    its message is the error and no file is left."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    log = tmp_path / "ffmpeg.json"
    fake = bin_dir / "ffmpeg"
    fake.write_text(FAKE_FFMPEG.format(python=sys.executable, log=str(log), fail=fail))
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", str(bin_dir))
    out = tmp_path / "out" / "fig1.mp4"
    if fail:
        with pytest.raises(OSError, match="ffmpeg could not write .*fig1.mp4.*Unknown encoder 'libx264'"):
            animate_run(fig1, out, frames=7, fps=5, width=320)
        assert not out.exists() and not list(out.parent.glob("*partial*"))
        return
    animation = animate_run(fig1, out, frames=7, fps=5, width=320)
    pixel_map = animation.pixel_map
    called = json.loads(log.read_text())
    args = called["args"]
    assert args[args.index("-s") + 1] == f"{pixel_map.width}x{pixel_map.height}" and args[args.index("-r") + 1] == "5"
    assert pixel_map.width % 2 == 0 and pixel_map.height % 2 == 0   # yuv420p needs even sides
    assert called["bytes"] == 7 * pixel_map.width * pixel_map.height * 3
    assert out.read_bytes()[4:8] == b"ftyp" and not list(out.parent.glob("*partial*"))


# ---- the command line -------------------------------------------------------------------------

def cli(*args, env=None) -> subprocess.CompletedProcess:
    return subprocess.run([str(HINF_CPP), *map(str, args)], capture_output=True, text=True, timeout=120, env=env)


@needs_cli
def test_cli_animate(tmp_path):
    out = tmp_path / "anim" / "fig1.gif"
    r = cli("animate", hc.scenario_path("paper_fig1"), "-o", out, "--frames", "12", "--fps", "10", "--marine")
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert f"wrote {out} (12 frames at 10 fps" in r.stdout
    with Image.open(out) as image:
        assert image.n_frames == 12 and image.info["duration"] == 100


@needs_cli
@pytest.mark.parametrize("args, message", [
    (["--frames", "1"], "argument --frames: invalid frame count '1'"),
    (["--frames", "many"], "argument --frames: invalid frame count 'many'"),
    (["--fps", "0"], "argument --fps: invalid frame rate '0'"),
    (["--width", "10"], "argument --width: invalid width '10'"),
    (["-o", "{tmp}/run.avi"], "must end in .gif or .mp4"),
    (["-o", "{tmp}/run.mp4"], "MP4 needs ffmpeg on PATH"),
    (["-o", "{tmp}/plain/run.gif"], "not a directory"),
])
def test_cli_animate_bad_options_one_line(tmp_path, args, message):
    if "-o" not in args:
        args = ["-o", "{tmp}/run.gif", *args]
    (tmp_path / "plain").write_text("a plain file, not a folder")
    env = {**os.environ, "PATH": str(tmp_path)}   # no ffmpeg
    r = cli("animate", hc.scenario_path("paper_fig1"), *[a.format(tmp=tmp_path) for a in args], env=env)
    assert r.returncode == 2, (r.stdout, r.stderr)
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("hinf-cpp") and message in lines[0], r.stderr
    assert r.stdout == "" and not list(tmp_path.glob("run.*"))
