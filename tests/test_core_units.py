import numpy as np
import pytest

from glyphbench_rl.core import ActionSet, Frame, build_frame, cell_names, check_frame, seeding
from glyphbench_rl.core.frame import is_single_width


def test_action_resolution_order():
    acts = ActionSet([("MOVE_LEFT", "go left"), ("NOOP", "wait")], aliases={"west": "MOVE_LEFT"}, noop="NOOP")
    assert acts.index("MOVE_LEFT") == 0
    assert acts.index(" move left ") == 0 and acts.index("Move-Left") == 0
    assert acts.index("WEST") == 0 and acts.noop == 1
    assert acts.index(np.int64(1)) == 1
    with pytest.raises(ValueError, match="valid actions: MOVE_LEFT, NOOP"):
        acts.index("jump")
    with pytest.raises(ValueError, match="out of range"):
        acts.index(2)
    with pytest.raises(ValueError, match="out of range"):
        acts.index(True)


def test_actionset_rejects_bad_declarations():
    with pytest.raises(ValueError, match="duplicate"):
        ActionSet([("A", "x"), ("A", "y")])
    with pytest.raises(ValueError, match="differ only in case"):
        ActionSet([("up", "x"), ("UP", "y")])
    with pytest.raises(ValueError, match="unknown action"):
        ActionSet([("A", "x")], aliases={"b": "C"})


def test_grouped_actions_share_a_prompt_line():
    acts = ActionSet([("PASS", "skip")], groups=[("press that cell", cell_names(2, 2))])
    assert acts.names == ("PASS", "A1", "B1", "A2", "B2")
    assert acts.prompt_lines() == ["PASS: skip", "A1 B1 A2 B2: press that cell"]


def test_frame_legend_follows_vocab_order_and_presence():
    f = build_frame(["#.", ".@"], {"@": "you", "#": "wall", ".": "floor", "*": "food"}, "Step 0/5")
    assert [g for g, _ in f.legend] == ["@", "#", "."]
    assert f.render() == "Step 0/5\n#.\n.@\nLegend: @ you, # wall, . floor"
    with pytest.raises(RuntimeError, match="no legend entry"):
        build_frame(["#?"], {"#": "wall"}, "Step 0/5")


def test_axes_rendering():
    f = build_frame(["●·", "··"], {"●": "lit", "·": "off"}, "Step 0/9", axes=True)
    assert f.render().splitlines()[1:4] == ["  AB", "1 ●·", "2 ··"]


def test_check_frame_catches_violations():
    good = Frame(("ab", "ba"), (("a", "x"), ("b", "y")), "Step 0/1")
    assert check_frame(good) == []
    assert "not rectangular" in check_frame(Frame(("ab", "b"), good.legend, "Step 0/1"))[0]
    assert any("single-width" in p for p in check_frame(Frame(("a漢",), (("a", "x"), ("漢", "y")), "S")))
    assert any("legend keys" in p for p in check_frame(Frame(("aa",), (("a", "x"), ("b", "y")), "S")))
    assert not is_single_width(" ") and not is_single_width("\u0301") and is_single_width("█")


def test_seed_ranges_and_streams():
    assert seeding.split_of(5) == "train" and seeding.split_of(1_500_000) == "heldout"
    assert seeding.heldout_seeds(3) == [1_000_000, 1_000_001, 1_000_002]
    a = seeding.training_seeds(0, 100)
    assert len(set(a)) == 100 and all(s in seeding.TRAIN_SEEDS for s in a)
    assert a == seeding.training_seeds(0, 100) and a != seeding.training_seeds(1, 100)
    x = seeding.generator(3, "level").integers(1 << 30, size=4)
    y = seeding.generator(3, "dynamics").integers(1 << 30, size=4)
    assert not np.array_equal(x, y)
    with pytest.raises(TypeError):
        seeding.check_seed(1.0)
    with pytest.raises(ValueError):
        seeding.check_seed(-1)


def test_comma_lists_mix_globs_and_ids():
    from glyphbench_rl.core import resolve_tasks
    ids = resolve_tasks("glyphbench/classics-snake-*, glyphbench/classics-2048-v0")
    assert ids[-1] == "glyphbench/classics-2048-v0" and len(ids) == 4


def test_catalog_task_not_yet_implemented_says_so():
    import pytest
    from glyphbench_rl.core import UnknownTaskError, make
    with pytest.raises(UnknownTaskError, match="in the GlyphBench catalog but not implemented"):
        make("glyphbench/minihack-boxoban-hard-v0")
