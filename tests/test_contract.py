"""The task contract, checked on every registered task: later games are covered for free."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import gymnasium
import pytest
from gymnasium.utils.env_checker import check_env

import glyphbench_rl
from glyphbench_rl.core import EpisodeEnded, check_frame, get_spec
from glyphbench_rl.core.task import STANDARD_TURN_CAP

from contract_play import digest, play

ROOT = Path(__file__).resolve().parents[1]
STEP_RE = re.compile(r"^Step (\d+)/(\d+)(?: \| |$)")


def test_gymnasium_env_checker(task_id):
    """Gymnasium's checker as users call it (render check included: it resets a fresh task
    without a seed); any warning it gives is an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(gymnasium.make(task_id))


def test_gymnasium_make_and_render(task_id):
    env = gymnasium.make(task_id, render_mode="ansi")
    obs, info = env.reset(seed=3)
    assert env.render() == obs
    obs, reward, term, trunc, info = env.step(0)
    assert isinstance(obs, str) and isinstance(reward, float)
    env.close()


def test_same_seed_same_episode(task_id):
    _, a = play(task_id, 11, max_steps=200, forfeit_every=7)
    _, b = play(task_id, 11, max_steps=200, forfeit_every=7)
    assert a == b


def test_determinism_across_processes():
    ids = glyphbench_rl.list_tasks()
    here = digest(ids)
    for hashseed in ("0", "4242"):
        env = dict(os.environ, PYTHONHASHSEED=hashseed)
        out = subprocess.run([sys.executable, str(ROOT / "tests" / "contract_play.py"), *ids],
                             capture_output=True, text=True, env=env, check=True, cwd=ROOT)
        assert json.loads(out.stdout) == here, f"PYTHONHASHSEED={hashseed} changed an episode"


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_003])
def test_random_play_to_the_end(task_id, seed):
    spec = get_spec(task_id)
    task, trace = play(task_id, seed)
    assert task.done
    assert task.turn <= task.max_turns == spec.max_turns
    if spec.tier == "standard":
        assert spec.max_turns <= STANDARD_TURN_CAP
        assert -1.0 <= task.episode_return <= 1.0
        assert not task._clamped, "the reward design relied on the clamp"
    if task._truncated:
        assert task.turn == task.max_turns


def test_rendering_contract(task_id):
    task = glyphbench_rl.make(task_id)
    obs, info = task.reset(seed=5)
    rng = glyphbench_rl.core.seeding.generator(5, "render-test")
    total = 0.0
    for _ in range(task.max_turns):
        frame = info["frame"]
        assert check_frame(frame) == [], check_frame(frame)
        m = STEP_RE.match(frame.hud)
        assert m and int(m.group(1)) == task.turn and int(m.group(2)) == task.max_turns, frame.hud
        assert obs == frame.render()
        assert obs in task.observation_space
        assert frame.legend[0][0] in obs
        if task.done:
            break
        obs, reward, term, trunc, info = task.step(int(rng.integers(task.action_space.n)))
        total += reward
        assert info["return"] == pytest.approx(total)


def test_forfeit_changes_nothing_but_the_turn(task_id):
    task = glyphbench_rl.make(task_id)
    _, info = task.reset(seed=9)
    before = info["frame"]
    obs, reward, term, trunc, info = task.forfeit("no_tag")
    after = info["frame"]
    assert reward == 0.0 and not term and task.turn == 1
    assert after.grid == before.grid
    assert after.hud.split(" | ", 1)[1:] == before.hud.split(" | ", 1)[1:]
    assert info["forfeit"] and info["forfeit_reason"] == "no_tag"
    while not task.done:
        _, reward, term, trunc, _ = task.forfeit()
        assert reward == 0.0 and not term
    assert trunc and task.turn == task.max_turns and task.episode_return == 0.0


def test_after_the_end_is_refused(task_id):
    task = glyphbench_rl.make(task_id, max_turns=2)
    task.reset(seed=0)
    task.forfeit()
    task.forfeit()
    assert task.done
    with pytest.raises(EpisodeEnded, match="already ended"):
        task.step(0)
    with pytest.raises(EpisodeEnded):
        task.forfeit()
    obs, _ = task.reset(seed=0)  # a new episode is fine
    assert task.turn == 0 and not task.done


def test_system_prompt_names_every_action(task_id):
    task = glyphbench_rl.make(task_id)
    prompt = task.system_prompt()
    for name in task.actions.names:
        assert re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", prompt), name
    assert f"after {task.max_turns} turns" in prompt
    assert "{" not in prompt and "}" not in prompt
    assert "<action>" in prompt


def test_bad_actions_and_seeds(task_id):
    task = glyphbench_rl.make(task_id)
    with pytest.raises(TypeError, match="int seed"):
        task.reset(seed="7")
    with pytest.raises(RuntimeError, match="reset"):
        task.step(0)
    task.reset(seed=1)
    n = task.action_space.n
    for bad in (n, -1, "NOT_AN_ACTION", 1.5, None):
        with pytest.raises(ValueError, match="valid actions"):
            task.step(bad)
    assert task.turn == 0
    name = task.actions[0].name
    task.step(name.lower())  # names resolve case-insensitively
    assert task.turn == 1


def test_ids_match_the_catalog(task_id):
    rows = {}
    for line in (ROOT / "tasks" / "catalog.tsv").read_text().splitlines()[1:]:
        suite, tier, tid, *_ = line.split("\t")
        rows[tid] = (suite, tier)
    spec = get_spec(task_id)
    assert rows.get(task_id) == (spec.suite, spec.tier)
