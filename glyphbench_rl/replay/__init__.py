"""The replay viewers (web page, terminal, images) and plots over trajectory records.

The record itself, ``Trajectory``/``Step``, lives in ``glyphbench_rl.rollout.trajectory``.
"""
