"""Animations of a run: the vessel as a hull oriented by its heading, the desired position as a
ghost hull, the trail of the path behind it (GIF with Pillow; MP4 through ffmpeg).

The frames are drawn with Pillow's ``ImageDraw`` directly rather than rendered by matplotlib:
a frame costs about a millisecond instead of tens (a hundred frames take well under a
second), the frames are palette images with a fixed palette, so the GIF holds the exact
colours drawn (no quantization, no dithering), and the world-to-pixel map is one affine map,
returned as :class:`PixelMap` so that a frame can be read back against the run.

The view is sized to the data: the desired and actual paths over the run, with equal scale on
both axes and a margin. With ``marine=True`` it is drawn in the marine convention (North up,
East right: for the ship x is North and y is East, so y is horizontal and x vertical).

The options' defaults and bounds (``DEFAULT_FRAMES``, ``MAX_FPS``, ...) are those of
:mod:`~hinf_cpp.output.animation_options`, importable from here too.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
import os
import pathlib
import shutil
import subprocess

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from hinf_cpp import _core
from hinf_cpp.output.animation_options import (DEFAULT_FPS, DEFAULT_FRAMES, DEFAULT_WIDTH, MAX_FPS, MAX_FRAMES,
                                               MAX_WIDTH, MIN_WIDTH)
from hinf_cpp.output.files import atomic_output, check_output_path
from hinf_cpp.output.tables import run_key

__all__ = [
    "ANIMATION_SUFFIXES",
    "VESSEL_RGB",
    "Animation",
    "PixelMap",
    "animate_run",
    "check_animation_path",
]

#: The file endings an animation can be written as (.mp4 needs ffmpeg on PATH).
ANIMATION_SUFFIXES = (".gif", ".mp4")

# The fixed palette of the frames (index: colour).
_BACKGROUND, _DESIRED, _GHOST, _TRAIL, _VESSEL, _TEXT, _START = range(7)
_PALETTE = [(255, 255, 255), (190, 190, 190), (90, 90, 90), (140, 180, 225), (31, 119, 180), (0, 0, 0),
            (120, 120, 120)]
#: The colour of the vessel's hull in every frame (RGB), used by no other element.
VESSEL_RGB = _PALETTE[_VESSEL]

# The hull in body axes (forward, starboard), as fractions of its length: a pointed bow, a
# square stern. Shifted below so that its area centroid is the vehicle's position.
_HULL = np.array([[0.5, 0.0], [0.2, 0.17], [-0.5, 0.17], [-0.5, -0.17], [0.2, -0.17]])


def _area_centroid(polygon: np.ndarray) -> np.ndarray:
    x, y = polygon[:, 0], polygon[:, 1]
    cross = x * np.roll(y, -1) - np.roll(x, -1) * y
    area = 0.5 * cross.sum()
    return np.array([((x + np.roll(x, -1)) * cross).sum(), ((y + np.roll(y, -1)) * cross).sum()]) / (6.0 * area)


_HULL = _HULL - _area_centroid(_HULL)


@dataclasses.dataclass(frozen=True)
class PixelMap:
    """The world-to-pixel map of an animation's frames: equal scale on both axes.

    A point (x, y) of the plane is drawn at column ``origin[0] + scale * h`` and row
    ``origin[1] - scale * v`` (rows grow downwards), where (h, v) = (x, y), or (y, x) in the
    marine convention (North up, East right).

    Parameters
    ----------
    width : int
        Frame width (pixels).
    height : int
        Frame height (pixels).
    scale : float
        Pixels per unit of length.
    origin : tuple of float
        The pixel (column, row) of the world's (h, v) = (0, 0).
    marine : bool
        True: y horizontal (East, right) and x vertical (North, up).

    Examples
    --------
    >>> from hinf_cpp.output.animation import PixelMap
    >>> pixel_map = PixelMap(width=200, height=100, scale=10.0, origin=(100.0, 50.0), marine=False)
    >>> pixel_map.to_pixel(1.0, 2.0)
    (110.0, 30.0)
    >>> PixelMap(200, 100, 10.0, (100.0, 50.0), marine=True).to_pixel(1.0, 2.0)  # x North, y East
    (120.0, 40.0)
    """

    width: int
    height: int
    scale: float
    origin: tuple[float, float]
    marine: bool

    def to_pixel(self, x, y):
        """The pixel (column, row) of world point(s) (x, y): floats, or arrays of the same shape."""
        h, v = (y, x) if self.marine else (x, y)
        return self.origin[0] + self.scale * h, self.origin[1] - self.scale * v

    def direction(self, psi):
        """The unit direction (columns, rows) in the frame of a heading psi (rad, from x towards y)."""
        dx, dy = np.cos(psi), np.sin(psi)
        dh, dv = (dy, dx) if self.marine else (dx, dy)
        return dh, -dv


@dataclasses.dataclass
class Animation:
    """What :func:`animate_run` wrote.

    Parameters
    ----------
    path : pathlib.Path
        The file written (GIF or MP4).
    frames : int
        The number of frames.
    fps : float
        Frames per second (a GIF's delay is rounded to hundredths of a second).
    times : numpy.ndarray
        The run's time at each frame (s): evenly spaced from its first to its last output time.
    pixel_map : PixelMap
        The world-to-pixel map of every frame.

    Examples
    --------
    >>> from hinf_cpp.output.animation import animate_run
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> animation = animate_run(result, "fig1.gif", frames=10)
    >>> animation.path.name, animation.frames, float(animation.times[-1])
    ('fig1.gif', 10, 40.0)
    """

    path: pathlib.Path
    frames: int
    fps: float
    times: np.ndarray
    pixel_map: PixelMap


def _check_options(frames, fps, width) -> None:
    if isinstance(frames, bool) or not isinstance(frames, numbers.Integral) or not 2 <= frames <= MAX_FRAMES:
        raise ValueError(f"frames must be an integer in [2, {MAX_FRAMES}], got {frames!r}")
    if isinstance(fps, bool) or not isinstance(fps, numbers.Real) or not (0.0 < fps <= MAX_FPS):
        raise ValueError(f"fps must be a number in (0, {MAX_FPS:g}] (a GIF stores each frame's delay in "
                         f"hundredths of a second), got {fps!r}")
    if isinstance(width, bool) or not isinstance(width, numbers.Integral) or not MIN_WIDTH <= width <= MAX_WIDTH:
        raise ValueError(f"width must be an integer in [{MIN_WIDTH}, {MAX_WIDTH}] (pixels), got {width!r}")


def check_animation_path(path: str | os.PathLike) -> pathlib.Path:
    """Check, before a run, that an animation can be written at a path.

    The path must be writable (:func:`hinf_cpp.output.files.check_output_path`) and end in
    .gif or .mp4; an .mp4 needs ``ffmpeg`` on PATH.

    Parameters
    ----------
    path : str or os.PathLike
        The file.

    Returns
    -------
    pathlib.Path
        The path.

    Raises
    ------
    ValueError
        Naming the path and what is wrong.

    Examples
    --------
    >>> from hinf_cpp.output.animation import check_animation_path
    >>> check_animation_path("out/run.gif").name
    'run.gif'
    >>> check_animation_path("run.avi")
    Traceback (most recent call last):
        ...
    ValueError: cannot write the animation 'run.avi': its name must end in .gif or .mp4 (.mp4 needs ffmpeg on PATH)
    """
    path = pathlib.Path(path)
    suffix = path.suffix.lower()
    if suffix not in ANIMATION_SUFFIXES:
        raise ValueError(f"cannot write the animation '{path}': its name must end in .gif or .mp4 "
                         "(.mp4 needs ffmpeg on PATH)")
    if suffix == ".mp4" and shutil.which("ffmpeg") is None:
        raise ValueError(f"cannot write the animation '{path}': MP4 needs ffmpeg on PATH (install ffmpeg, "
                         "or write a .gif)")
    check_output_path(path)
    return path


def _pixel_map(points: np.ndarray, width: int, marine: bool) -> PixelMap:
    """Equal scale, the data centred, a margin of 6% of the width (plus a band for the text at
    the top); the height follows the data's aspect, between half and one and a half widths."""
    h, v = (points[:, 1], points[:, 0]) if marine else (points[:, 0], points[:, 1])
    lo = np.array([h.min(), v.min()])
    hi = np.array([h.max(), v.max()])
    span = np.maximum(hi - lo, 1e-9)
    # A straight path would give a strip one line high: at least a fifth of the longer side.
    span = np.maximum(span, 0.2 * span.max())
    margin = max(12, int(0.06 * width))
    band = 34  # two lines of text above the view
    inner_w = width - 2 * margin
    height = int(np.clip(round(inner_w * span[1] / span[0]) + 2 * margin + band, width // 2, 3 * width // 2))
    height += height % 2  # MP4 (yuv420p) needs even sides
    inner_h = height - 2 * margin - band
    scale = min(inner_w / span[0], inner_h / span[1])
    centre = 0.5 * (lo + hi)
    origin = (0.5 * width - scale * centre[0], band + margin + 0.5 * inner_h + scale * centre[1])
    return PixelMap(width, height, float(scale), (float(origin[0]), float(origin[1])), marine)


def _hull(pixel_map: PixelMap, x: float, y: float, psi: float, length: float) -> list[tuple[float, float]]:
    """The hull's corners in pixels: centred (area centroid) on (x, y), its bow along psi."""
    c, s = math.cos(psi), math.sin(psi)
    wx = x + length * (c * _HULL[:, 0] - s * _HULL[:, 1])
    wy = y + length * (s * _HULL[:, 0] + c * _HULL[:, 1])
    px, py = pixel_map.to_pixel(wx, wy)
    return list(zip(px.tolist(), py.tolist()))


def _scale_bar(draw: ImageDraw.ImageDraw, pixel_map: PixelMap, unit: str, font) -> None:
    """A bar of 1, 2 or 5 times a power of ten, about a fifth of the width, at the bottom left."""
    target = 0.2 * pixel_map.width / pixel_map.scale
    power = 10.0 ** math.floor(math.log10(target))
    length = max(m * power for m in (1.0, 2.0, 5.0) if m * power <= target)
    x0, y0 = 10, pixel_map.height - 12
    x1 = x0 + length * pixel_map.scale
    draw.line([(x0, y0), (x1, y0)], fill=_TEXT, width=2)
    draw.line([(x0, y0 - 4), (x0, y0 + 2)], fill=_TEXT)
    draw.line([(x1, y0 - 4), (x1, y0 + 2)], fill=_TEXT)
    draw.text((x1 + 6, y0 - 7), f"{length:g} {unit}", fill=_TEXT, font=font)


def _time_format(step: float) -> str:
    """Enough decimals that consecutive frames' times differ (a GIF merges identical frames)."""
    return f".{max(1, math.ceil(-math.log10(step)) + 1)}f" if step > 0 else ".3f"


def animate_run(result: _core.RunResult, path: str | os.PathLike, *, frames: int = DEFAULT_FRAMES,
                fps: float = DEFAULT_FPS, width: int = DEFAULT_WIDTH, marine: bool = False,
                length_unit: str = "m") -> Animation:
    """Write an animation of a run: the vessel, the desired position and the trail of the path.

    Each frame shows the desired path (light grey), the trail of the actual path up to the
    frame's time (light blue), the desired position as a ghost hull (outline) and the vessel as
    a filled hull (blue) oriented by its heading, with its area centroid at the vehicle's
    position, the time, and a scale bar. The frames' times are evenly spaced from the run's
    first to its last output time (the last frame is the run's final state; a run that
    diverged ends where it stopped), states interpolated linearly between output times.

    Parameters
    ----------
    result : hinf_cpp.RunResult
        The run, of a model with a planar position and a heading.
    path : str or os.PathLike
        The file: .gif (Pillow), or .mp4 (needs ffmpeg on PATH). Written whole or not at all.
    frames : int, optional
        The number of frames, 2 to 2000 (default 100).
    fps : float, optional
        Frames per second, in (0, 50] (default 20).
    width : int, optional
        Frame width in pixels, 160 to 4096 (default 640); the height follows the data.
    marine : bool, optional
        Marine convention: North up, East right (x vertical, y horizontal; default False: x
        right, y up).
    length_unit : str, optional
        The unit of the scale bar (the model's unit of length; default ``"m"``).

    Returns
    -------
    Animation
        The path, frame count, frame rate, frame times and the world-to-pixel map.

    Raises
    ------
    ValueError
        Options out of range (naming the option), a path that cannot be written or does not
        end in .gif or .mp4, .mp4 without ffmpeg, a model without a planar position or a
        heading.
    OSError
        The file could not be written, or ffmpeg failed (its message).

    Examples
    --------
    >>> from hinf_cpp.output.animation import animate_run
    >>> result = hc.run_scenario(hc.load_scenario(hc.scenario_path("paper_fig1")))
    >>> animation = animate_run(result, "fig1.gif", frames=20, fps=10, marine=True)
    >>> animation.frames, animation.fps, animation.pixel_map.marine
    (20, 10, True)
    >>> animate_run(result, "fig1.gif", frames=1)
    Traceback (most recent call last):
        ...
    ValueError: frames must be an integer in [2, 2000], got 1
    """
    _check_options(frames, fps, width)
    path = check_animation_path(path)
    model = result.trajectory.model()
    indices = model.position_indices()
    heading = model.heading_index()
    if len(indices) != 2 or heading < 0:
        raise ValueError(f"an animation needs a planar position and a heading: the model '{model.name()}' "
                         "has " + ("no heading" if len(indices) == 2 else "no planar position"))
    ix, iy = indices
    sim = result.simulation
    t = np.asarray(sim.t)
    q = np.asarray(sim.q)
    q_d = np.asarray(sim.q_d)
    finite = np.all(np.isfinite(q[:, [ix, iy, heading]]), axis=1)
    t, q, q_d = t[finite], q[finite], q_d[finite]
    times = np.linspace(t[0], t[-1], frames)

    def at(series: np.ndarray, column: int) -> np.ndarray:
        return np.interp(times, t, series[:, column])

    x, y, psi = at(q, ix), at(q, iy), at(q, heading)
    xd, yd, psid = at(q_d, ix), at(q_d, iy), at(q_d, heading)
    points = np.vstack([q[:, [ix, iy]], q_d[:, [ix, iy]]])
    pixel_map = _pixel_map(points, int(width), marine)
    span = float(max(np.ptp(points[:, 0]), np.ptp(points[:, 1]), 1e-9))
    length = max(0.06 * span, 14.0 / pixel_map.scale)  # the hull: at least 14 pixels long

    font = ImageFont.load_default()
    base = Image.new("P", (pixel_map.width, pixel_map.height), _BACKGROUND)
    base.putpalette([c for colour in _PALETTE for c in colour])
    draw = ImageDraw.Draw(base)
    draw.fontmode = "1"  # no anti-aliasing: palette images hold only the palette's colours
    desired_px = np.column_stack(pixel_map.to_pixel(q_d[:, ix], q_d[:, iy]))
    draw.line([tuple(p) for p in desired_px.tolist()], fill=_DESIRED, width=2)
    sx, sy = pixel_map.to_pixel(q[0, ix], q[0, iy])
    draw.rectangle([sx - 3, sy - 3, sx + 3, sy + 3], outline=_START)
    _scale_bar(draw, pixel_map, length_unit, font)
    axes = "North up, East right (x up, y right)" if marine else "x right, y up"
    status = sim.status.name
    title = f"{result.scenario_name}: {run_key(result.law, result.output_feedback)}" + \
        ("" if status == "completed" else f" ({status})")
    draw.text((8, 4), title, fill=_TEXT, font=font)
    actual_px = np.column_stack(pixel_map.to_pixel(q[:, ix], q[:, iy]))
    time_format = _time_format((times[-1] - times[0]) / (frames - 1))

    images = []
    for k, tk in enumerate(times):
        image = base.copy()
        frame = ImageDraw.Draw(image)
        frame.fontmode = "1"
        upto = int(np.searchsorted(t, tk, side="right"))
        trail = [tuple(p) for p in actual_px[:upto].tolist()] + [pixel_map.to_pixel(float(x[k]), float(y[k]))]
        if len(trail) >= 2:
            frame.line(trail, fill=_TRAIL, width=2)
        frame.polygon(_hull(pixel_map, float(xd[k]), float(yd[k]), float(psid[k]), length), outline=_GHOST)
        hull = _hull(pixel_map, float(x[k]), float(y[k]), float(psi[k]), length)
        frame.polygon(hull, fill=_VESSEL, outline=_VESSEL)
        frame.text((8, 18), f"t = {tk:{time_format}} s   ghost: desired   {axes}", fill=_TEXT, font=font)
        images.append(image)

    if path.suffix.lower() == ".mp4":
        _write_mp4(images, path, fps)
    else:
        with atomic_output(path) as handle:  # whole or not at all
            images[0].save(handle, format="GIF", save_all=True, append_images=images[1:],
                           duration=int(round(1000.0 / fps)), loop=0, optimize=False)
    return Animation(path, int(frames), fps, times, pixel_map)


def _write_mp4(images: list[Image.Image], path: pathlib.Path, fps: float) -> None:
    """H.264 through ffmpeg, written beside and renamed over `path` once complete."""
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        raise ValueError(f"cannot write the animation '{path}': MP4 needs ffmpeg on PATH (install ffmpeg, "
                         "or write a .gif)")
    width, height = images[0].size
    partial = path.with_name(f".{path.name}.partial.mp4")
    path.parent.mkdir(parents=True, exist_ok=True)
    command = [ffmpeg, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{width}x{height}",
               "-r", f"{fps:g}", "-i", "-", "-pix_fmt", "yuv420p", "-vcodec", "libx264", str(partial)]
    data = b"".join(image.convert("RGB").tobytes() for image in images)
    try:
        finished = subprocess.run(command, input=data, capture_output=True, check=False)
        if finished.returncode != 0:
            message = " ".join(finished.stderr.decode(errors="replace").split()) or f"exit status {finished.returncode}"
            raise OSError(f"ffmpeg could not write '{path}': {message}")
        os.replace(partial, path)
    finally:
        if partial.exists():
            partial.unlink()
