"""Mechanics more than one family uses; a family imports ``core`` and ``common``, never another
family, and nothing here imports a family.

- ``palette``: the shared glyphs (wall, floor, unseen, goal, player, lava).
- ``grid``: compass moves, a mutable char ``Board``, walled rooms, 4-way BFS and shortest paths,
  sliding until blocked, BFS over any hashable state.
- ``sight``: exact lines of sight between cells and a watcher's view cone.
- ``lanes``: shuffled bags, cyclic lanes that slide with the tick, random runs of objects.
- ``view``: a window onto a long scrolling course, sprites drawn over it, signed HUD numbers.
- ``physics``: integer gravity and tunnel-free vertical sweeps; projectile flight over terrain.
- ``waves``: enemies with hit points, spawn schedules and cells, path walkers, wanderers,
  marching formations, turret volleys.
- ``boards``: one action per board cell, bitboards (flood fills, regions), run-length clues.
- ``pushing``: box pushing under Sokoban rules: rooms as bitmasks, the push-optimal A* solver,
  reverse play (random pulling runs, and every pull state by breadth-first layers).
"""
