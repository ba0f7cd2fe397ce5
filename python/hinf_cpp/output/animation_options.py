"""The options of an animation (:func:`hinf_cpp.output.animation.animate_run`): their defaults and
bounds.

Apart from :mod:`~hinf_cpp.output.animation` so that the command line states them in its help
without loading NumPy and Pillow; :mod:`~hinf_cpp.output.animation` takes them from here and
they can be imported from either.

Examples
--------
>>> from hinf_cpp.output.animation_options import DEFAULT_FRAMES, MAX_FRAMES
>>> DEFAULT_FRAMES, MAX_FRAMES
(100, 2000)
"""

from __future__ import annotations

__all__ = ["DEFAULT_FPS", "DEFAULT_FRAMES", "DEFAULT_WIDTH", "MAX_FPS", "MAX_FRAMES", "MAX_WIDTH", "MIN_WIDTH"]

#: Frames of an animation unless told otherwise.
DEFAULT_FRAMES = 100
#: Frames per second unless told otherwise.
DEFAULT_FPS = 20.0
#: Width of the frames (pixels) unless told otherwise; the height follows the data.
DEFAULT_WIDTH = 640
#: The most frames of an animation.
MAX_FRAMES = 2000
#: The highest frame rate: a GIF stores each frame's delay in hundredths of a second.
MAX_FPS = 50.0
#: The narrowest frames (pixels).
MIN_WIDTH = 160
#: The widest frames (pixels).
MAX_WIDTH = 4096
