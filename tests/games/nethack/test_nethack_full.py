"""Full NetHack (glyphbench/nethack-full-v0): NLE's challenge game on the MiniHack wrapper, the
full command set by name, the score as reward, and reproducible episodes (seeded character)."""

from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from nle import nethack

import glyphbench_rl
from glyphbench_rl.core import check_frame, get_spec, seeding
from glyphbench_rl.core.params import ParamError
from glyphbench_rl.games.nethack import engine, full, render

ID = "glyphbench/nethack-full-v0"
ROOT = Path(__file__).resolve().parents[3]
ACTIONS = ["MOVE_E", "FAR_S", "SEARCH", "MOVE_W", "NUM_2", "SEARCH", "PICKUP", "EAT", "MOVE_N",
           "FAR_W", "KICK", "LOOK", "TRAVEL", "FIGHT", "MOVE_E", "INVENTORY", "WAIT", "MOVE_NE"]

DIGEST = """
import hashlib, json, sys
import glyphbench_rl
task = glyphbench_rl.make({id!r})
h = hashlib.sha256()
for seed in (0, 5):
    obs, _ = task.reset(seed=seed)
    h.update(obs.encode())
    for a in {actions!r}:
        if task.done:
            break
        obs, r, term, trunc, _ = task.step(a)
        h.update(f"{{obs}}|{{r!r}}|{{term}}".encode())
print(json.dumps([h.hexdigest(), task.character]))
"""


def _digest_here() -> list:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(DIGEST.format(id=ID, actions=ACTIONS), {})
    return json.loads(out.getvalue())


def test_registered_lazily_as_extended_with_its_horizon():
    spec = get_spec(ID)
    assert spec.tier == "extended" and spec.suite == "NetHack"
    assert spec.game == "glyphbench_rl.games.nethack.full:NetHackFull"
    assert spec.max_turns == 10_000


def test_the_action_set_is_nle_full_list_by_name():
    keys = {int(a) for a in nethack.ACTIONS}
    assert set(full.FULL_KEYS.values()) == keys              # every NLE key has one name
    assert len(full.FULL_ACTIONS) == len(keys) == len(nethack.ACTIONS) - 3
    for name in engine.ACTIONS.names:                        # the MiniHack names keep their keys
        if name != "WIELD":                                  # (there: any equipment; here: w)
            assert full.FULL_KEYS[name] == engine.KEYS[name], name
    assert full.FULL_KEYS["WIELD"] == ord("w") and full.FULL_KEYS["WEAR"] == ord("W")
    assert full.FULL_KEYS["FAR_N"] == ord("K") and full.FULL_KEYS["CAST"] == ord("Z")
    for alias, name in (("DOLLAR", "SEEGOLD"), ("PLUS", "SEESPELLS"), ("QUOTE", "SEEAMULET")):
        assert full.FULL_ACTIONS.lookup(alias) == full.FULL_ACTIONS.lookup(name)
    assert all(a.description and "\n" not in a.description for a in full.FULL_ACTIONS)


def test_make_reset_step_and_the_hud():
    task = glyphbench_rl.make(ID)
    obs, info = task.reset(seed=0)
    assert check_frame(info["frame"]) == []
    hud = info["frame"].hud
    assert hud.startswith("Step 0/10000 | " + task.character + " | Dlvl 1 ")
    assert "Score 0" in hud and "HP " in hud and "Inv a " in hud
    assert task.character.split()[0] in ("lawful", "neutral", "chaotic")
    x = task.hero[0]
    obs, reward, term, trunc, info = task.step("MOVE_E")
    assert task.turn == 1 and not term and not trunc
    assert task.hero[0] in (x, x + 1)


def test_the_seed_picks_the_character():
    task = glyphbench_rl.make(ID)
    seen = set()
    for seed in (0, 1, 2, 3, 0):
        task.reset(seed=seed)
        seen.add((seed, task.character))
    assert len({c for _, c in seen}) >= 3                    # random across seeds ...
    assert len(seen) == 4                                    # ... the same for one seed
    valk = glyphbench_rl.make(ID, character="val")          # a role: NetHack draws the rest
    valk.reset(seed=0)
    assert valk.character.endswith(" Valkyrie")
    assert "a val (NetHack's role abbreviation" in valk.system_prompt()
    with pytest.raises(ParamError, match="character must be one of '@', 'arc'"):
        glyphbench_rl.make(ID, character="valkyrie")


def test_same_seed_and_actions_same_episode_in_another_process():
    here = _digest_here()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]),
               PYTHONHASHSEED="123")
    out = subprocess.run([sys.executable, "-c", DIGEST.format(id=ID, actions=ACTIONS)], cwd=ROOT,
                         env=env, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert json.loads(out.stdout.splitlines()[-1]) == here


def test_random_play_keeps_the_contract_and_pays_the_score():
    task = glyphbench_rl.make(ID)
    rng = seeding.generator(4, "nethack-full-random")
    ending = {task.actions.lookup(n) for n in ("UP", "QUIT")}   # (they end the game at once)
    allowed = [i for i in range(len(task.actions)) if i not in ending]
    steps = 0
    for seed in (4, 40):
        obs, info = task.reset(seed=seed)
        while not task.done and task.turn < 150:
            obs, reward, term, trunc, info = task.step(int(rng.choice(allowed)))
            steps += 1
            assert check_frame(info["frame"]) == []
            assert obs == info["frame"].render()
            if not term:      # the return is NetHack's score (it starts at 0)
                assert task.episode_return == int(task.obs("blstats")[nethack.NLE_BL_SCORE])
    assert steps >= 200


def test_death_ends_the_episode_as_lost():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    for _ in range(30):                       # praying again and again angers the god
        _, reward, term, trunc, info = task.step("PRAY")
        if term:
            break
    assert term and not trunc and info["won"] is False
    assert task.env.nethack.how_done() == nethack.DIED
    assert info["frame"].hud.endswith("| Dead")


def test_leaving_the_dungeon_ends_it_without_a_win():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)                         # NetHack starts you on the staircase up
    _, reward, term, trunc, info = task.step("UP")
    assert term and info["won"] is False and reward == 0.0
    assert info["frame"].hud.endswith("| Escaped the dungeon")


def test_commands_that_wait_for_more_leave_no_pending_input():
    task = glyphbench_rl.make(ID)
    for name in ("EXTCMD", "GLANCE", "TRAVEL", "JUMP"):
        task.reset(seed=0)
        t0 = int(task.obs("blstats")[nethack.NLE_BL_TIME])
        _, _, _, _, info = task.step(name)
        assert not info["frame"].message.startswith(("#", "Where do you want", "Pick an"))
        task.step("SEARCH")                    # a plain command works at once: the clock moves
        assert int(task.obs("blstats")[nethack.NLE_BL_TIME]) > t0, name
    task.reset(seed=0)
    _, _, _, _, info = task.step("FIGHT")     # a prefix: the next action completes it
    assert info["frame"].message == ""


def test_system_prompt():
    task = glyphbench_rl.make(ID)
    prompt = task.system_prompt()
    assert prompt.startswith("You are playing NetHack, the full game.")
    assert "a yes/no question gets yes" in prompt and "TRAVEL's, which picks the staircase down" in prompt
    assert "WIELD picks" not in prompt          # (the MiniHack set's WIELD, not NetHack's)
    assert "change of NetHack's score" in prompt and "after 10000 turns" in prompt
    assert "NUM_0 NUM_1" in prompt and "FAR_N FAR_E" in prompt
    assert "{" not in prompt


def test_rules_text_is_derived_from_the_minihack_rules():
    # the full game's answer rules are the MiniHack ones less WIELD's: fail loudly if the
    # MiniHack wording changes and the derivation stops removing it
    assert full.FULL_ANSWER_RULES.startswith(engine.ANSWER_RULES.split(" WIELD")[0])
    assert "WIELD" in engine.ANSWER_RULES and "WIELD" not in full.FULL_ANSWER_RULES


def test_travel_and_descending_pay_the_score_and_show_the_new_level():
    task = glyphbench_rl.make(ID)
    task.reset(seed=30)                       # the staircase down is in view from the start
    assert ">" in "".join(task.frame.grid)
    x0 = task.hero[0]
    task.step("TRAVEL")
    assert task.hero[0] > x0                   # on its way east to the staircase
    rewards = []
    for name in ["TRAVEL", "MOVE_E", "MOVE_E", "MOVE_E", "TRAVEL", "TRAVEL", "DOWN"]:  # (a rat)
        rewards.append(task.step(name)[1])
    hud = task.frame.hud
    assert " Dlvl 2 " in hud and "View" not in hud
    assert rewards[-1] == 50.0                 # NetHack's score: 50 for each level below the first
    assert task.episode_return == int(task.obs("blstats")[nethack.NLE_BL_SCORE])
    assert max(len(row) for row in task.frame.grid) < 41   # the new level's seen part only
    for name in ["MOVE_W", "MOVE_S", "MOVE_S"]:        # the painter draws the new level's window
        task.step(name)
        assert list(task.frame.grid) == render.grid_rows(
            task.obs("chars"), task.obs("glyphs"), task.obs("screen_descriptions"), task._bounds,
            task.hero, task.glyph_map)
