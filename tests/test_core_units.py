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


def test_text_above_and_beside_the_board():
    f = build_frame(["●·", "··"], {"●": "lit", "·": "off"}, "Step 0/9", axes=True)._replace(
        above=("1", "12"), beside=("1", ""))
    assert f.render().splitlines()[1:6] == ["  1", "  12", "  AB", "1 ●· 1", "2 ··"]
    assert check_frame(f) == []
    assert "2 beside notes for 1 rows" in check_frame(Frame(("a",), (("a", "x"),), "S", beside=("1", "2")))


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


def test_catalog_task_not_yet_implemented_says_so(monkeypatch):
    """(Every catalog task is implemented now: a build without one is made by unregistering it.)"""
    import pytest
    from glyphbench_rl.core import UnknownTaskError, make, registry
    monkeypatch.delitem(registry._REGISTRY, "glyphbench/atari-pitfall-v0")
    with pytest.raises(UnknownTaskError, match="in the GlyphBench catalog but not implemented"):
        make("glyphbench/atari-pitfall-v0")


SNAKE = "glyphbench/classics-snake-easy-v0"


def test_named_streams_are_per_episode_deterministic_and_leave_the_main_rng_alone():
    from glyphbench_rl.core import make
    a, b = make(SNAKE), make(SNAKE)
    with pytest.raises(RuntimeError, match="reset"):
        a.stream("mobs")
    a.reset(seed=5)
    b.reset(seed=5)
    mobs = a.stream("mobs")
    assert a.stream("mobs") is mobs and a.stream("mobs", 2) is not mobs
    x = mobs.integers(1 << 62, size=8)
    assert np.array_equal(x, seeding.generator(5, "mobs").integers(1 << 62, size=8))   # the seed's "mobs"
    assert np.array_equal(x, b.stream("mobs").integers(1 << 62, size=8))
    assert not np.array_equal(x, a.stream("plants").integers(1 << 62, size=8))
    a.stream("mobs").random(1000)                                   # drawing here ...
    assert a.np_random.bit_generator.state == b.np_random.bit_generator.state   # ... moves nothing there
    for move in ["UP", "RIGHT", "RIGHT", "DOWN", "DOWN", "LEFT"] * 3:       # same food, same game
        assert a.step(move)[:4] == b.step(move)[:4]
        if a.done:
            break
    a.reset(seed=5)
    assert a.stream("mobs") is not mobs and np.array_equal(a.stream("mobs").integers(1 << 62, size=8), x)
    a.reset(seed=6)
    assert not np.array_equal(a.stream("mobs").integers(1 << 62, size=8), x)
    a.reset(seed=5)
    a.reset()                                                       # continues the seeded stream
    assert not np.array_equal(a.stream("mobs").integers(1 << 62, size=8), x)
    with pytest.raises(TypeError, match="string"):
        a.stream(0)


def test_derived_sequences_match_seed_sequence():
    parent = np.random.SeedSequence(11)
    assert (seeding.derive(parent, "level", 3).generate_state(4)
            == seeding.seed_sequence(11, "level", 3).generate_state(4)).all()
    child = parent.spawn(1)[0]
    assert not np.array_equal(seeding.derive(child, "a").generate_state(4),
                              seeding.derive(parent, "a").generate_state(4))


def test_nle_seeds_are_stable_distinct_and_in_range():
    core, disp, lgen = seeding.nle_seeds(7)
    assert seeding.nle_seeds(7) == (core, disp, lgen) == seeding.nle_seeds(np.random.SeedSequence(7))
    assert all(type(v) is int and 0 <= v < 2**63 for v in (core, disp, lgen))
    assert len({core, disp, lgen}) == 3
    many = [seeding.nle_seeds(s) for s in range(500)]
    assert len({s for triple in many for s in triple}) == 1500
    assert seeding.nle_seeds(np.random.SeedSequence(7).spawn(1)[0]) != (core, disp, lgen)
    with pytest.raises(TypeError):
        seeding.nle_seeds(7.0)


def test_jax_key_material_is_stable_distinct_and_in_range():
    key = seeding.jax_key_data(3)
    assert key.shape == (2,) and key.dtype == np.uint32
    assert np.array_equal(key, seeding.jax_key_data(3))
    assert np.array_equal(key, seeding.jax_key_data(np.random.SeedSequence(3)))
    keys = {tuple(int(w) for w in seeding.jax_key_data(s)) for s in range(500)}
    assert len(keys) == 500
    ints = [seeding.jax_seed(s) for s in range(500)]
    assert all(type(v) is int and 0 <= v < 2**31 for v in ints) and len(set(ints)) == 500
    assert ints == [seeding.jax_seed(s) for s in range(500)]
    with pytest.raises(ValueError):
        seeding.jax_seed(-1)


def test_jax_accepts_the_key_material():
    jax = pytest.importorskip("jax")
    a = jax.random.uniform(jax.random.PRNGKey(seeding.jax_seed(3)))
    assert a == jax.random.uniform(jax.random.PRNGKey(seeding.jax_seed(3)))
    key = jax.random.wrap_key_data(seeding.jax_key_data(3))
    assert jax.random.uniform(key) == jax.random.uniform(jax.random.wrap_key_data(seeding.jax_key_data(3)))
