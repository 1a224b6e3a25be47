"""The Craftax observation (``games/craftax/view.py``): glyphs, the grid and its darkness, the HUD,
the rules text.

``data/view_states.npz`` holds 15 states converted from the ``craftax`` package (one generated
world, the player put on each of the nine floors, on dark floors far from any light, at an
overworld corner at night asleep, next to the necromancer with no summons, by a torch in the
dark; mobs and projectiles of the floor's kinds placed around the player), each with upstream's
symbolic observation of it (``render_craftax_symbolic``: 9 x 11 cells of 37 block + 5 item + 40
mob one-hots + 1 light bit). The tests compare our grid with that observation without jax;
``python tests/games/craftax/test_craftax_view.py OUT.npz`` regenerates the file (needs the
package; about two minutes).
"""

from __future__ import annotations

from dataclasses import fields
from pathlib import Path

import numpy as np
import pytest

from glyphbench_rl.core.frame import is_single_width, legend_of, vocab_entries
from glyphbench_rl.games.craftax import hud, view
from glyphbench_rl.games.craftax.state import Inventory, Mobs, Settings, State
from glyphbench_rl.games.craftax.tables import Action, BlockType, ItemType, ProjectileType

DATA = Path(__file__).parent / "data" / "view_states.npz"
MOB_CLASSES = ("melee_mobs", "passive_mobs", "ranged_mobs", "mob_projectiles", "player_projectiles")
N_BLOCKS, N_ITEMS = 37, 5


def load_states(path: Path = DATA) -> list[tuple[State, np.ndarray]]:
    """(state, upstream symbolic map 9 x 11 x 83) for every state in the fixture; a state's
    arrays are stored once when equal to state 0's."""
    data = np.load(path)
    out = []
    for i in range(int(data["count"])):
        def get(name, i=i):
            key = f"{i}/{name}"
            return data[key] if key in data.files else data[f"0/{name}"]
        kw = {}
        for f in fields(State):
            if f.name in MOB_CLASSES:
                kw[f.name] = Mobs.from_arrays(*(get(f"{f.name}.{g.name}") for g in fields(Mobs)))
            elif f.name == "inventory":
                kw[f.name] = Inventory(**{
                    g.name: (get(f"inventory.{g.name}").copy() if g.name in ("armour", "potions")
                             else int(get(f"inventory.{g.name}"))) for g in fields(Inventory)})
            else:
                value = get(f.name)
                kw[f.name] = value.copy() if value.ndim else value.item()
        out.append((State(**kw), get("symbolic_map")))
    return out


@pytest.fixture(scope="module")
def states():
    return load_states()


def mob_glyph(mob_class: int, type_id: int) -> str:
    if mob_class < 3:
        return (view.MELEE_GLYPHS, view.PASSIVE_GLYPHS, view.RANGED_GLYPHS)[mob_class][type_id][0]
    glyphs = view.MOB_PROJECTILE_GLYPHS if mob_class == 3 else view.PLAYER_PROJECTILE_GLYPHS
    return glyphs[view.PROJECTILE_KIND[ProjectileType(type_id)]][0]


# ---- glyphs ------------------------------------------------------------------------------

def test_every_glyph_is_one_single_width_character_with_one_meaning():
    entries = [*view.PLAYER_GLYPHS.values(), *view.MELEE_GLYPHS, *view.PASSIVE_GLYPHS,
               *view.RANGED_GLYPHS, *view.MOB_PROJECTILE_GLYPHS, *view.PLAYER_PROJECTILE_GLYPHS,
               *view.ITEM_GLYPHS.values(), *view.BLOCK_GLYPHS.values(), view.DARK]
    glyphs = [g for g, _ in entries]
    assert len(set(glyphs)) == len(glyphs), "a glyph with two meanings"
    assert len({m for _, m in entries}) == len(entries), "two glyphs with one meaning"
    assert all(is_single_width(g) for g in glyphs)
    assert view.VOCAB == dict(entries)


def test_every_thing_upstream_can_show_has_a_glyph():
    assert set(view.BLOCK_GLYPHS) == set(BlockType)
    assert set(view.ITEM_GLYPHS) == set(ItemType) - {ItemType.NONE}
    assert set(view.PLAYER_GLYPHS) == {0, Action.LEFT, Action.RIGHT, Action.UP, Action.DOWN}
    assert len(view.MELEE_GLYPHS) == len(view.RANGED_GLYPHS) == 8   # upstream's texture lists
    assert len(view.PASSIVE_GLYPHS) == 3
    assert set(view.PROJECTILE_KIND) == set(ProjectileType)
    # the lookup table draws only vocabulary glyphs
    assert set(view._TABLE.values()) - {"\n"} <= set(view.VOCAB)
    assert view.BLOCK_GLYPHS[BlockType.GRASS][0] == "."


# ---- the grid against upstream's symbolic observation ------------------------------------

def test_the_fixture_covers_every_floor(states):
    assert {s.player_level for s, _ in states} == set(range(9))


def test_grid_shape_and_vocabulary(states):
    for state, _ in states:
        rows = view.grid(state)
        assert len(rows) == 9 and all(len(r) == 11 for r in rows)
        assert set("".join(rows)) <= set(view.VOCAB)
        assert {g for g, _ in legend_of("".join(rows), vocab_entries(view.VOCAB))} == set("".join(rows))


def test_darkness_and_map_edge_match_upstreams_visibility(states):
    dark, edge = view.DARK[0], view.BLOCK_GLYPHS[BlockType.OUT_OF_BOUNDS][0]
    seen_dark = 0
    for state, symbolic in states:
        rows = view.grid(state)
        pr, pc = state.player_position.tolist()
        for r in range(9):
            for c in range(11):
                if (r, c) == (4, 5):
                    continue
                row, col = pr - 4 + r, pc - 5 + c
                inside = 0 <= row < 48 and 0 <= col < 48
                lit = bool(symbolic[r, c, -1])
                if not inside:
                    assert rows[r][c] == edge and not lit
                else:
                    assert (rows[r][c] == dark) == (not lit), (state.player_level, r, c)
                    seen_dark += not lit
    assert seen_dark > 200    # the dark floors' cells really are dark


def test_every_visible_cell_shows_what_upstream_shows(states):
    for state, symbolic in states:
        rows = view.grid(state)
        level = state.player_level
        for r in range(9):
            for c in range(11):
                cell = symbolic[r, c]
                if (r, c) == (4, 5) or not cell[-1]:
                    continue
                mobs = np.flatnonzero(cell[N_BLOCKS + N_ITEMS:-1])
                item = int(np.argmax(cell[N_BLOCKS:N_BLOCKS + N_ITEMS]))
                block = int(np.argmax(cell[:N_BLOCKS]))
                assert cell[:N_BLOCKS].sum() == 1
                if len(mobs):
                    expected = mob_glyph(*divmod(int(mobs[-1]), 8))
                elif item:
                    if item == ItemType.LADDER_DOWN and state.monsters_killed[level] < 8:
                        item = ItemType.LADDER_DOWN_BLOCKED
                    expected = view.ITEM_GLYPHS[ItemType(item)][0]
                else:
                    if block == BlockType.NECROMANCER and view.is_boss_vulnerable(state):
                        block = BlockType.NECROMANCER_VULNERABLE
                    expected = view.BLOCK_GLYPHS[BlockType(block)][0]
                assert rows[r][c] == expected, (level, r, c, rows)


def test_the_fixture_shows_mobs_of_every_class(states):
    shown = "".join("".join(view.grid(s)) for s, _ in states)
    for glyphs in (view.MELEE_GLYPHS, view.PASSIVE_GLYPHS, view.RANGED_GLYPHS):
        assert sum(g in shown for g, _ in glyphs) >= 3
    assert view.BLOCK_GLYPHS[BlockType.NECROMANCER_VULNERABLE][0] in shown
    assert view.ITEM_GLYPHS[ItemType.TORCH][0] in shown


def test_player_glyph_follows_facing_and_sleep(states):
    state = states[0][0].copy()
    for direction, glyph in (("LEFT", "←"), ("RIGHT", "→"), ("UP", "↑"), ("DOWN", "↓")):
        state.player_direction = int(Action[direction])
        assert view.grid(state)[4][5] == glyph
    state.is_sleeping = True
    assert view.grid(state)[4][5] == view.PLAYER_GLYPHS[0][0]


def test_a_down_ladder_is_locked_until_eight_kills(states):
    state = states[0][0].copy()
    level, (pr, pc) = state.player_level, state.player_position.tolist()
    state.item_map[level, pr, pc + 1] = ItemType.LADDER_DOWN
    state.light_map[level] = 1.0
    for killed, glyph in ((7, "]"), (8, ">")):
        state.monsters_killed[level] = killed
        assert view.grid(state)[4][6] == glyph


def test_mobs_in_the_dark_are_hidden(states):
    state = states[0][0].copy()
    level, (pr, pc) = state.player_level, state.player_position.tolist()
    state.melee_mobs.mask[level] = [True] + [False] * (len(state.melee_mobs.mask[level]) - 1)
    state.melee_mobs.position[level][0] = (pr, pc + 2)
    state.melee_mobs.type_id[level][0] = 0
    assert view.grid(state)[4][7] == "z"
    state.light_map[level, pr, pc + 2] = 0.05      # at the threshold: not visible
    assert view.grid(state)[4][7] == view.DARK[0]


# ---- the HUD -----------------------------------------------------------------------------

def test_hud_of_a_fresh_overworld_state(states):
    state = states[0][0]
    text = hud.hud(state, Settings())
    assert text.startswith("HP 9 Food 9 Drink 9 Energy 9 Mana 9 (max 9) | ")
    assert "Floor 0 Overworld at 24,24" in text and "Day" in text
    assert "Kills" not in text         # the overworld's ladder starts open (kills 10)
    assert "Potions" not in text and "Spells" not in text and "XP" not in text


def test_hud_lists_inventory_gear_and_status(states):
    state = states[1][0].copy()          # the dungeon
    inv = state.inventory
    inv.wood, inv.coal, inv.pickaxe, inv.sword, inv.bow, inv.arrows = 3, 2, 2, 4, 1, 5
    inv.armour[:] = (1, 0, 2, 0)
    inv.potions[:] = (0, 2, 0, 0, 0, 1)
    state.sword_enchantment, state.armour_enchantments[2] = 2, 1
    state.learned_spells[:] = (True, False)
    state.player_xp, state.player_strength, state.player_health = 2, 2, 7.25
    state.monsters_killed[1], state.is_resting = 3, True
    text = hud.hud(state)
    for part in ("HP 7.2/10 Food 9/9 Drink 9/9 Energy 9/9 Mana 9/9", "Wood 3 Coal 2 Arrows 5", "stone pickaxe", "ice diamond sword",
                 "bow", "iron helmet", "fire diamond legs", "Potions green 2 yellow 1",
                 "Spells fireball", "XP 2 Str 2 |", "Floor 1 Dungeon", "Kills 3/8",
                 "Resting"):
        assert part in text, part
    assert "Stone" not in text and "chest" not in text   # zero counts and empty slots left out
    state.player_level = 8
    assert "Kills" not in hud.hud(state)   # the graveyard has no ladder down


def test_hud_light(states):
    night = next(s for s, _ in states if s.player_level == 0 and s.is_sleeping)
    assert "Night" in hud.hud(night) and "Sleeping" in hud.hud(night)
    dark = next(s for s, _ in states if s.player_level == 5)
    assert " dark" in hud.hud(dark)


# ---- the rules text ----------------------------------------------------------------------

def test_rules_text_is_built_from_the_tables():
    text = view.rules_text()
    assert "iron pickaxe/iron sword 1 wood+1 stone+1 iron+1 coal" in text
    assert "place table 2 wood" in text and "iron pickaxe: diamond" in text
    assert "no tool: tree" in text and "ladder down" in text and "Food, drink" in text
    fight = view.rules_text(topics=("fight",), drains=False)
    assert "wood pickaxe" not in fight and "ladder" not in fight and "Food" not in fight
    custom = view.rules_text(recipes=(("MAKE_GOLD_HAT", {"gold": 4}, False, True),))
    assert "furnace: gold hat 4 gold" in custom and "wood pickaxe/wood sword" not in custom
    assert "{" not in text and "}" not in text     # safe inside GlyphTask's str.format template


def _generate(out_path: str) -> None:
    """Build the fixture from the craftax package (jax): one world, 15 placements."""

    import jax
    import jax.numpy as jnp
    from craftax.craftax.constants import FLOOR_MOB_MAPPING, RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING, TORCH_LIGHT_MAP
    from craftax.craftax.craftax_state import EnvParams, StaticEnvParams
    from craftax.craftax.renderer import render_craftax_symbolic
    from craftax.craftax.world_gen.world_gen import generate_world

    base = generate_world(jax.random.PRNGKey(7), EnvParams(), StaticEnvParams())
    render = jax.jit(render_craftax_symbolic)

    def place(mobs, level, slot, pos, type_id):
        return mobs.replace(position=mobs.position.at[level, slot].set(jnp.array(pos)),
                            mask=mobs.mask.at[level, slot].set(True),
                            type_id=mobs.type_id.at[level, slot].set(type_id),
                            health=mobs.health.at[level, slot].set(3.0))

    def clear(mobs):
        return mobs.replace(mask=jnp.zeros_like(mobs.mask))

    variants = []
    for level in range(9):
        if level == 0:
            pos = np.array(base.player_position)
        else:
            pos = np.array(base.up_ladders[level])
        variants.append(dict(level=level, pos=pos, mobs=True, direction=1 + level % 4))
    # far from the light on dark floors, a corner of the overworld at night asleep,
    # an open ladder, a vulnerable necromancer, a torch in the dark
    variants.append(dict(level=2, pos=np.array([10, 12]), mobs=False, direction=2))
    variants.append(dict(level=5, pos=np.array([30, 30]), mobs=True, direction=4))
    variants.append(dict(level=0, pos=np.array([2, 45]), mobs=True, direction=3, night=True, sleeping=True))
    variants.append(dict(level=1, pos=np.array(base.down_ladders[1]), mobs=False, direction=1, killed=8))
    nec = np.argwhere(np.array(base.map[8]) == 32)
    variants.append(dict(level=8, pos=nec[0] + np.array([0, 2]) if len(nec) else np.array([24, 24]), mobs=False, direction=1, vulnerable=True))
    variants.append(dict(level=7, pos=np.array(base.up_ladders[7]) + np.array([3, 3]), mobs=False, direction=2, torch=(1, 2)))

    states, obs = [], []
    for v in variants:
        s = base
        level = v["level"]
        pos = np.clip(v["pos"], 0, 47)
        s = s.replace(player_level=jnp.int32(level), player_position=jnp.array(pos, dtype=jnp.int32),
                      player_direction=jnp.int32(v["direction"]))
        s = s.replace(melee_mobs=clear(s.melee_mobs), passive_mobs=clear(s.passive_mobs),
                      ranged_mobs=clear(s.ranged_mobs), mob_projectiles=clear(s.mob_projectiles),
                      player_projectiles=clear(s.player_projectiles),
                      boss_timesteps_to_spawn_this_round=jnp.int32(0 if v.get("vulnerable") else 5))
        if v["mobs"]:
            passive_t, melee_t, ranged_t = (int(x) for x in FLOOR_MOB_MAPPING[level])
            near = lambda d: np.clip(pos + np.array(d), 0, 47)
            s = s.replace(melee_mobs=place(s.melee_mobs, level, 0, near((0, 2)), melee_t),
                          passive_mobs=place(s.passive_mobs, level, 1, near((2, 0)), passive_t),
                          ranged_mobs=place(s.ranged_mobs, level, 0, near((-2, -3)), ranged_t),
                          mob_projectiles=place(s.mob_projectiles, level, 2, near((1, 4)),
                                                int(RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING[ranged_t])),
                          player_projectiles=place(s.player_projectiles, level, 0, near((-1, -1)),
                                                   [4, 2, 3][level % 3]))
        if v.get("night"):
            s = s.replace(light_level=jnp.float32(0.1))
        if v.get("sleeping"):
            s = s.replace(is_sleeping=jnp.bool_(True))
        if v.get("killed"):
            s = s.replace(monsters_killed=s.monsters_killed.at[level].set(v["killed"]))
        if v.get("torch"):
            tp = pos + np.array(v["torch"])
            s = s.replace(item_map=s.item_map.at[level, tp[0], tp[1]].set(1))
            lm = np.array(s.light_map[level])
            pad = np.pad(lm, 6)
            pad[tp[0] + 6 - 4:tp[0] + 6 + 5, tp[1] + 6 - 4:tp[1] + 6 + 5] = np.clip(
                pad[tp[0] + 6 - 4:tp[0] + 6 + 5, tp[1] + 6 - 4:tp[1] + 6 + 5] + np.array(TORCH_LIGHT_MAP), 0, 1)
            s = s.replace(light_map=s.light_map.at[level].set(jnp.array(pad[6:-6, 6:-6])))
        states.append(s)
        obs.append(np.array(render(s)))

    out = {}
    names = [f for f in base.__dataclass_fields__ if f not in ("state_rng", "fractal_noise_angles")]
    for i, s in enumerate(states):
        for name in names:
            value = getattr(s, name)
            if hasattr(value, "__dataclass_fields__"):
                for sub in value.__dataclass_fields__:
                    out[f"{i}/{name}.{sub}"] = np.array(getattr(value, sub))
            else:
                out[f"{i}/{name}"] = np.array(value)
        # upstream's symbolic map part: 9 x 11 x (37 blocks + 5 items + 40 mobs + 1 light)
        out[f"{i}/symbolic_map"] = obs[i][: 9 * 11 * 83].reshape(9, 11, 83).astype(np.uint8)
    # the states share their world: store each array once when equal to state 0's
    for key in list(out):
        i, name = key.split("/", 1)
        if i != "0" and name != "symbolic_map" and np.array_equal(out[key], out["0/" + name]):
            del out[key]
    np.savez_compressed(out_path, count=len(states), **out)
    print("saved", len(states))


if __name__ == "__main__":   # regenerate the fixture from the craftax package
    import sys
    _generate(sys.argv[1])
