"""The shortcuts of the step path give what the plain computations give: numpy's integers,
a legend computed from scratch every frame, the Frame's own constructor."""

import copy
import pickle
import random

import numpy as np
import pytest

from glyphbench_rl.core import ActionSet, Frame, GlyphTask, seeding
from glyphbench_rl.core import frame as frame_module
from glyphbench_rl.core.frame import new_frame, render


def test_int_sampler_is_numpy_integers_call_for_call():
    pick = random.Random(7)
    for seed in range(300):
        ours, theirs = (np.random.Generator(np.random.PCG64(seed)) for _ in range(2))
        draw = seeding.int_sampler(ours)
        for _ in range(40):
            low = pick.randrange(-40, 40)
            span = pick.choice([1, 2, 3, 7, 100, pick.randrange(1, 2**32), 2**31 + pick.randrange(2**31),
                                2**32, 2**40])
            if pick.random() < 0.2:           # other draws in between share the buffered half-word
                assert ours.random() == theirs.random()
            if pick.random() < 0.1:
                low, high = np.int64(low), np.int64(low + span)
            else:
                high = low + span
            got = draw(low, high)
            assert got == int(theirs.integers(low, high)) and type(got) is int
        assert ours.bit_generator.state == theirs.bit_generator.state
    with pytest.raises(ValueError, match="low >= high"):
        draw(3, 3)


class Scripted(GlyphTask):
    """Shows a scripted grid each turn, from a vocabulary that can change mid-episode."""
    title = "scripted"
    ACTIONS = ActionSet([(str(i), "show that grid") for i in range(6)])
    GRIDS = (["ab", "ba"], ["ab", "bc"], ["aa", "aa"], ["ab", "ba"], ["cc", "ac"], ["ab", "bc"])
    default_max_turns = 200

    def _init(self):
        self.words = {"c": "cee", "a": "ay", "b": "bee", "xy": "never on a grid"}

    def vocab(self):
        return self.words

    def _setup(self, rng):
        self.shown = 0

    def _act(self, action):
        self.shown = action
        if action == 5:
            self.words = {"a": "AY", "b": "BEE", "c": "CEE"}   # a new vocabulary object

    def _grid(self):
        return self.GRIDS[self.shown]


def test_legend_shortcuts_match_a_plain_legend():
    task = Scripted()
    task.reset(seed=0)
    for action in [0, 1, 1, 2, 3, 0, 4, 5, 1, 0, 2, 5, 3, 4, 4, 1] * 3:
        obs, *_ , info = task.step(action)
        frame, grid = info["frame"], task.GRIDS[action]
        present = set("".join(grid))
        assert frame.legend == tuple((g, m) for g, m in task.words.items() if g in present)
        assert obs == render(Frame(tuple(grid), frame.legend, frame.hud, frame.message))


def test_a_glyph_without_legend_entry_still_fails_after_shortcuts():
    task = Scripted()
    task.reset(seed=0)
    task.step(0)
    task.GRIDS = (["ab", "bz"],) * 6
    with pytest.raises(RuntimeError, match="'z' are on the grid but have no legend entry"):
        task.step(0)


def test_new_frame_is_the_named_tuple():
    args = (("ab",), (("a", "x"), ("b", "y")), "Step 1/2", "hi", True)
    fast, plain = new_frame(*args), Frame(*args)
    assert type(fast) is Frame and fast == plain and hash(fast) == hash(plain)
    assert repr(fast) == repr(plain) and fast._asdict() == plain._asdict()
    assert fast.above == fast.beside == () and fast.render() == plain.render()
    with pytest.raises(AttributeError):
        fast.hud = "x"


class Counter(GlyphTask):
    """Never shows the same grid twice: every row is new to the legend memo."""
    title = "counter"
    ACTIONS = ActionSet([("TICK", "count on")])
    glyphs = {str(d): f"digit {d}" for d in range(10)}
    default_max_turns = 2000

    def _setup(self, rng):
        self.n = 0

    def _act(self, action):
        self.n += 1

    def _grid(self):
        return [f"{self.n:04d}"]


def test_legends_stay_right_when_the_row_memo_starts_again(monkeypatch):
    monkeypatch.setattr(frame_module, "ROW_MEMO", 50)
    task = Counter(tier="extended")
    task.reset(seed=0)
    for _ in range(130):
        _, _, _, _, info = task.step(0)
        digits = sorted(set(f"{task.n:04d}"), key=int)
        assert [g for g, _ in info["frame"].legend] == digits
        assert info["frame"].render().splitlines()[-1] == "Legend: " + ", ".join(
            f"{d} digit {d}" for d in digits)
    assert 0 < len(task._legend_memo.rows) <= 50


def test_the_legend_memo_is_shared_not_copied():
    task = Counter(tier="extended")
    task.reset(seed=0)
    task.step(0)
    twin = copy.deepcopy(task)
    assert twin._legend_memo is task._legend_memo
    assert pickle.loads(pickle.dumps(task))._legend_memo is task._legend_memo   # (same process)
    assert Counter(tier="extended")._legend_memo is not None


def test_a_steps_info_is_info_written_out():
    """``_finish_step`` writes ``_info`` out: the same keys and values."""
    from glyphbench_rl import make
    for task_id in ("glyphbench/classics-snake-easy-v0", "glyphbench/craftax-firstday-v0",
                    "glyphbench/minigrid-empty-5x5-v0"):
        task = make(task_id)
        task.reset(seed=0)
        for action in (0, 1, 2):
            info = task.step(action)[4]
            assert info == task._info(forfeit=False)
        info = task.forfeit("no_tag")[4]
        assert info == task._info(forfeit=True) | {"forfeit_reason": "no_tag"}
