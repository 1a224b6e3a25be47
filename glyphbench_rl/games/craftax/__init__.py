"""Craftax: upstream Craftax 1.6.1's rules as numpy tables and small sub-rules, and the suite's
Craftax tasks as scenarios on that one engine.

Modules: ``state`` (upstream's EnvState in numpy), ``tables`` (enumerations and constant tables),
``bestiary`` (mobs), ``rules`` (the step), ``mobs`` (mob movement, attacks, projectiles,
spawning), ``worldgen`` (the nine levels), ``view`` (the observation), ``task`` (the task
class), ``scenarios`` (the tasks as data). The ``craftax`` package itself is only a test oracle.
"""
