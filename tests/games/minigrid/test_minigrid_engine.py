"""MiniGrid engine semantics on hand-drawn levels: actions, doors, boxes, carrying, the view."""

from __future__ import annotations

import pytest

import glyphbench_rl
from glyphbench_rl.games.minigrid.engine import (DONE, DROP, FORWARD, LEFT, PICKUP, RIGHT, TOGGLE,
                                                  MiniGridTask)
from glyphbench_rl.games.minigrid.world import UNSEEN, Ball, Box, Door, Key


class Sandbox(MiniGridTask):
    """Any object may appear; the level comes from ``load_level``."""
    has_lava = True

    def _gen(self, rng):
        self.new_grid(3, 3)
        self.agent_pos, self.agent_dir = (1, 1), 0


def level(rows, **params):
    task = Sandbox(max_turns=100, **params)
    task.reset(seed=0)
    task.load_level(rows, mission="test")
    return task


ROOM = ["█████",
        "█···█",
        "█·▲·█",
        "█···█",
        "█████"]


def test_turns_change_only_the_facing():
    task = level(ROOM)
    for action, facing in ((LEFT, 2), (LEFT, 1), (RIGHT, 2), (RIGHT, 3), (RIGHT, 0)):
        task.step(action)
        assert task.agent_dir == facing and task.agent_pos == (2, 2)


def test_forward_moves_and_walls_block_silently():
    task = level(ROOM)
    task.step(FORWARD)
    assert task.agent_pos == (2, 1)
    _, reward, term, _, info = task.step(FORWARD)          # the wall: nothing happens
    assert task.agent_pos == (2, 1) and reward == 0 and not term and info["frame"].message == ""


def test_goal_wins_with_minigrids_time_discount():
    task = level(["████", "█▶◎█", "████"])
    task.step(LEFT)
    task.step(RIGHT)
    _, reward, term, _, _ = task.step(FORWARD)
    assert term and task.won and reward == pytest.approx(1 - 0.9 * 3 / task.max_turns)


def test_lava_ends_the_episode_with_nothing():
    task = level(["████", "█▶≈█", "████"])
    _, reward, term, _, info = task.step(FORWARD)
    assert term and task.won is False and reward == 0 and task.agent_pos == (2, 1)
    assert "lava" in info["frame"].message


def test_pickup_takes_only_the_cell_in_front_and_holds_one_thing():
    task = level(["██████", "█y▶ⓡ·█", "██████"])
    task.step(PICKUP)
    assert isinstance(task.carrying, Ball) and task.grid.get(3, 1) is None
    assert "Carrying: red ball" in task.frame.hud
    task.step(LEFT), task.step(LEFT)
    task.step(PICKUP)                                      # hands full: the key stays
    assert isinstance(task.carrying, Ball) and isinstance(task.grid.get(1, 1), Key)


def test_pickup_ignores_walls_and_doors():
    task = level(["█████", "█▶Y·█", "█████"])
    task.step(PICKUP)
    task.step(LEFT)
    task.step(PICKUP)
    assert task.carrying is None


def test_drop_only_onto_an_empty_cell():
    task = level(["██████", "█·▶ⓡ·█", "██████"])
    task.step(PICKUP)
    task.step(RIGHT), task.step(RIGHT)
    task.step(FORWARD)                                     # now at (1, 1) facing west: a wall
    task.step(DROP)
    assert isinstance(task.carrying, Ball)
    task.step(RIGHT), task.step(RIGHT)
    task.step(DROP)
    assert task.carrying is None and isinstance(task.grid.get(2, 1), Ball)
    task.step(PICKUP)
    task.step(FORWARD)                                     # (2, 1) is empty again: walk in
    task.step(FORWARD)                                     # (3, 1): empty since the first pickup
    task.step(DROP)
    assert isinstance(task.grid.get(4, 1), Ball)


def test_closed_door_blocks_then_toggles_open_and_shut():
    task = level(["██████", "█▶R·◎█", "██████"])
    task.step(FORWARD)
    assert task.agent_pos == (1, 1)
    task.step(TOGGLE)
    door = task.grid.get(2, 1)
    assert door.is_open and task.frame.grid  # the open door now draws as "_"
    task.step(FORWARD)
    assert task.agent_pos == (2, 1)
    task.step(FORWARD)
    task.step(LEFT), task.step(LEFT)
    task.step(TOGGLE)
    assert not door.is_open


def test_locked_door_needs_the_key_of_its_colour():
    task = level(["███████", "█b·▶Ⓨ◎█", "███████"])
    door = task.grid.get(4, 1)
    task.step(TOGGLE)
    assert door.is_locked and "locked" in task.frame.message
    task.step(LEFT), task.step(LEFT), task.step(FORWARD), task.step(PICKUP)   # the blue key
    assert isinstance(task.carrying, Key) and task.carrying.color == "blue"
    task.step(LEFT), task.step(LEFT), task.step(FORWARD), task.step(TOGGLE)
    assert door.is_locked and task.agent_pos == (3, 1)
    task.carrying = Key("yellow")
    task.step(TOGGLE)
    assert door.is_open and not door.is_locked and "unlocked" in task.frame.message
    task.step(TOGGLE)                                     # closes again, but stays unlocked
    assert not door.is_open and not door.is_locked
    task.carrying = None
    task.step(TOGGLE)
    assert door.is_open
    task.step(FORWARD), task.step(FORWARD)
    assert task.won


def test_box_turns_into_its_contents():
    task = level(["█████", "█▶⒭·█", "█████"])
    box = task.grid.get(2, 1)
    assert isinstance(box, Box)
    box.contains = Key("green")
    _, _, _, _, info = task.step(TOGGLE)
    assert isinstance(task.grid.get(2, 1), Key)
    assert "green key" in info["frame"].message
    task.step(TOGGLE)                                     # a key does not react
    assert isinstance(task.grid.get(2, 1), Key)
    task.load_level(["█████", "█▶⒭·█", "█████"])
    task.step(TOGGLE)                                     # an empty box vanishes
    assert task.grid.get(2, 1) is None


def test_done_does_nothing_by_default():
    task = level(ROOM)
    _, reward, term, trunc, _ = task.step(DONE)
    assert (reward, term, trunc) == (0, False, False) and task.agent_pos == (2, 2)


# -- the view ----------------------------------------------------------------------------------

OPEN = ["█████████",
        "█·······█",
        "█·······█",
        "█·······█",
        "█···▲···█",
        "█·······█",
        "█·······█",
        "█████████"]


@pytest.mark.parametrize("facing,slot", [("▲", (6, 3)), ("▶", (3, 0)), ("▼", (0, 3)), ("◀", (3, 6))])
def test_view_is_drawn_north_up_with_the_agent_on_its_back_edge(facing, slot):
    task = level([row.replace("▲", facing) for row in OPEN])
    grid = task.frame.grid
    assert len(grid) == 7 and all(len(r) == 7 for r in grid)
    assert grid[slot[0]][slot[1]] == facing


def test_walls_hide_what_is_behind_them_and_full_view_shows_it():
    rows = ["█████████",
            "█··y····█",
            "█████████",
            "█···▲···█",
            "█·······█",
            "█████████"]
    task = level(rows)
    view = task.frame.grid
    assert "y" not in "".join(view) and UNSEEN in "".join(view)
    assert view[5] == "███████" and set("".join(view[:5])) == {UNSEEN}  # the wall row, then nothing
    legend = task.frame.legend_dict()
    assert legend[UNSEEN] == "unseen"
    full = level(rows, view="full")
    assert full.frame.grid == tuple(r for r in rows) and UNSEEN not in "".join(full.frame.grid)


def test_opening_a_door_reveals_the_room_behind():
    rows = ["███████",
            "█··y··█",
            "███R███",
            "█··▲··█",
            "███████"]
    task = level(rows)
    assert "y" not in "".join(task.frame.grid)
    task.step(TOGGLE)
    assert "y" in "".join(task.frame.grid) and "_" in "".join(task.frame.grid)
    task.step(TOGGLE)
    assert "y" not in "".join(task.frame.grid)


def test_rooms_that_see_through_walls_have_no_unseen_cells():
    task = glyphbench_rl.make("glyphbench/minigrid-empty-8x8-v0")
    obs, info = task.reset(seed=0)
    assert UNSEEN not in obs and "unseen" not in task.system_prompt()
    assert info["frame"].grid[3].startswith("▶")      # facing east: the agent is on the west edge


def test_hud_has_the_mission_and_what_is_carried():
    task = glyphbench_rl.make("glyphbench/minigrid-doorkey-5x5-v0")
    obs, _ = task.reset(seed=0)
    assert "Mission: use the key to open the door and then get to the goal | Carrying: nothing" in obs
    nav = glyphbench_rl.make("glyphbench/minigrid-dynamic-obstacles-5x5-v0")
    nav.reset(seed=0)
    assert "Carrying" not in nav.frame.hud and nav.action_space.n == 3


def test_prompt_speaks_of_lava_only_where_there_is_lava():
    assert "lava" in glyphbench_rl.make("glyphbench/minigrid-crossing-n1-v0").system_prompt()
    assert "lava" not in glyphbench_rl.make("glyphbench/minigrid-crossing-n1-safe-v0").system_prompt()
    assert "lava" not in glyphbench_rl.make("glyphbench/minigrid-doorkey-5x5-v0").system_prompt()


def test_bad_view_parameter_is_refused():
    with pytest.raises(ValueError, match="view"):
        glyphbench_rl.make("glyphbench/minigrid-empty-5x5-v0", view="egocentric")


def test_door_glyphs_follow_its_state():
    door = Door("red")
    assert door.glyph == "R" and Door("red", is_locked=True).glyph == "Ⓡ"
    assert Door("red", is_open=True).glyph == "_"


@pytest.mark.parametrize("task_id", glyphbench_rl.list_tasks(suite="MiniGrid"))
def test_full_view_keeps_the_rendering_contract(task_id):
    from glyphbench_rl.core import check_frame
    task = glyphbench_rl.make(task_id, view="full")
    obs, info = task.reset(seed=1)
    for action in (2, 1, 2, 2, 0, 2):
        assert check_frame(info["frame"]) == [] and obs in task.observation_space
        assert len(info["frame"].grid) == task.grid.height and UNSEEN not in obs
        if task.done:
            break
        obs, _, _, _, info = task.step(action)
