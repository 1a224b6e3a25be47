"""Real trajectories for the replay tests: scripted policies played by the rollout engine."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Iterable

from glyphbench_rl.agent.harness import HarnessConfig
from glyphbench_rl.rollout.trajectory import Trajectory
from glyphbench_rl.rollout import EpisodeSpec, RolloutEngine, ScriptedBackend

SNAKE = "glyphbench/classics-snake-easy-v0"
EMPTY = "glyphbench/minigrid-empty-5x5-v0"
BATTLESHIP = "glyphbench/classics-battleship-v0"      # rendered with column letters and row numbers

# a reply that would run script if the page ever treated model text as markup
INJECTION = ('<script>window.__pwned = 1; document.title = "pwned"</script>'
             '<img src=x onerror="window.__pwned = 2; document.title = \'pwned\'">'
             ' and </script><!-- \u2028 & done')
FORFEIT_REPLY = "I am not sure what to do."
MEMORY = "Landmarks: <b>food</b> at the top & walls all round"


def scripted(request) -> str:
    """Turn 0: reasoning with injected markup, then a valid action; turn 1: no action (forfeit);
    later turns cycle through the action names, with a little reasoning."""
    names = request.actions.names
    if request.turn == 0:
        return f"<think>Plan: {INJECTION}</think>\n<action>{names[0]}</action>"
    if request.turn == 1:
        return FORFEIT_REPLY
    name = names[request.turn % len(names)]
    return f"<think>turn {request.turn}: try {name}</think><action>{name}</action>"


def forward(request) -> str:
    """Always the action called 'forward' (MiniGrid): bumps into a wall sooner or later."""
    return "<action>forward</action>"


def play(tasks: Iterable[str] = (SNAKE,), seeds: Iterable[int] = (1, 2), policy=scripted,
         harness: HarnessConfig | None = None) -> list[Trajectory]:
    engine = RolloutEngine(ScriptedBackend(policy), harness, meta={"model": "scripted-test", "split": "test"})
    trajs = engine.run([EpisodeSpec(t, s) for t in tasks for s in seeds])
    for traj in trajs:
        traj.steps[0].memory = MEMORY
    return trajs


def write_jsonl(path: Path, trajs: Iterable[Trajectory]) -> Path:
    path.write_text("".join(json.dumps(t.to_dict()) + "\n" for t in trajs), encoding="utf-8")
    return path
