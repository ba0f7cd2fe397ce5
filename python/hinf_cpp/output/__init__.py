"""What runs write and show: figures (:mod:`~hinf_cpp.output.plotting`, matplotlib), animations
of a run (:mod:`~hinf_cpp.output.animation`: GIF with Pillow, MP4 with ffmpeg; their options'
defaults and bounds in :mod:`~hinf_cpp.output.animation_options`), exports of
a run (:mod:`~hinf_cpp.output.export`: NPZ, CSV, JSON), the online controller as C99 code
(:mod:`~hinf_cpp.output.export_c`), tables
(:mod:`~hinf_cpp.output.tables`), files written whole or not at all
(:mod:`~hinf_cpp.output.files`) and progress lines (:mod:`~hinf_cpp.output.progress`).
Imported by name: nothing is loaded here.
"""
