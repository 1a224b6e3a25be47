"""MiniHack and NetHack on the real NetHack engine (``nle`` / ``minihack``, the ``nethack`` extra).

Light at import: this package registers its tasks from ``variants`` (data only); the engine
module (``engine``: the wrapper, NetHack's questions answered by rule, the renderer's use) is
imported by the registry only when one of these tasks is made. ``render`` turns NLE's arrays into
the grid, legend and HUD (numpy only); ``levels`` lists the MiniHack levels as data.
"""

from . import variants  # noqa: F401
