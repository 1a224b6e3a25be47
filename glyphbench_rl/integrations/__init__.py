"""Adapters to other RL stacks. Each lives in its own subpackage and imports its framework
only there, so ``import glyphbench_rl`` never pulls one in.

- ``verifiers_v1``: a Taskset, Env and Harness for verifiers 0.4 (``vf-eval glyphbench-rl``).
- ``prime_rl``: a training YAML rendered as Prime-RL's ``rl`` TOML on that taskset, and its launch.
"""
