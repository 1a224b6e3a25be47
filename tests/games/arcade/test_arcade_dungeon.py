"""The dungeon family (venture, tutankham): the engine's room-to-room world, monsters that wander
and chase, corpses; per game a scripted explorer that scores and reaches new rooms, a loss path,
and the signature mechanics."""

from __future__ import annotations

from collections import deque

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.dungeon import CORPSE

from arcade_play import play

NOOP, UP, DOWN, LEFT, RIGHT, FIRE = range(6)
MOVE = {(-1, 0): UP, (1, 0): DOWN, (0, -1): LEFT, (0, 1): RIGHT}


def danger(env) -> set:
    """Cells a careful explorer keeps off: monsters, corpses and the cells beside monsters."""
    cells = {(b.r, b.c) for b in env.corpses}
    movers = [(f.r, f.c) for f in env.foes]
    prowler = getattr(env, "prowler", None)
    if prowler is not None:
        movers.append(tuple(prowler))
    for r, c in movers:
        cells.update((r + a, c + b) for a in (-1, 0, 1) for b in (-1, 0, 1) if abs(a) + abs(b) <= 1)
    return cells


def route(env, targets, avoid) -> int | None:
    """The first move of a shortest path to a target cell, or None when none is reachable."""
    p, still = env.params, env.still
    start = (env.r, env.c)
    first = {start: None}
    queue = deque([start])
    while queue:
        cur = queue.popleft()
        if cur in targets and cur != start:
            while first[cur] != start and first[cur] is not None:
                cur = first[cur]
            return MOVE[(cur[0] - start[0], cur[1] - start[1])]
        for d in MOVE:
            nxt = (cur[0] + d[0], cur[1] + d[1])
            if nxt in first or not (0 <= nxt[0] < p.height and 0 <= nxt[1] < p.width):
                continue
            ch = still[nxt[0]][nxt[1]]
            if nxt in avoid or ch in env.SOLID or (ch in env.LINKS and nxt not in targets):
                continue
            first[nxt] = cur
            queue.append(nxt)
    return None


def in_sights(env) -> bool:
    """A monster that can be slain lies the way the gun points, within reach, in the clear."""
    dr, dc = env.aim if env.SIDEWAYS else env.face
    for k in range(1, env.params.reach + 1):
        r, c = env.r + dr * k, env.c + dc * k
        if not (0 <= r < env.params.height and 0 <= c < env.params.width) or env.still[r][c] in env.SOLID:
            return False
        foe = env.foe_at(r, c)
        if foe is not None:
            return foe.glyph not in env.IMMUNE
    return False


def explorer(env, targets, fire_ok=True) -> int:
    """Shoot what is in the sights, else walk a safe shortest path to a target, else keep away."""
    if fire_ok and in_sights(env) and env.gun.ready_at(env.tick + 1):
        return FIRE
    avoid = danger(env)
    move = route(env, targets, avoid)
    if move is None:
        move = route(env, targets, {(f.r, f.c) for f in env.foes} | {(b.r, b.c) for b in env.corpses})
        near = min((abs(f.r - env.r) + abs(f.c - env.c) for f in env.foes), default=99)
        if move is None or near <= 2:
            move = flee(env)
    return move


def flee(env) -> int:
    best, move = -1, NOOP
    for d, a in MOVE.items():
        r, c = env.r + d[0], env.c + d[1]
        if not (0 <= r < env.params.height and 0 <= c < env.params.width) or env.still[r][c] in env.SOLID \
                or env.still[r][c] in env.LINKS or env.foe_at(r, c) or env.corpse_at(r, c):
            continue
        far = min((abs(f.r - r) + abs(f.c - c) for f in env.foes), default=99)
        if far > best:
            best, move = far, a
    return move


# -- venture ------------------------------------------------------------------------------------------
VENTURE = "glyphbench/atari-venture-v0"


def cells_of(env, glyph) -> set:
    return {(r, c) for r, row in enumerate(env.still) for c, ch in enumerate(row) if ch == glyph}


def winky(env) -> int:
    if env.room == (1, 1):
        return explorer(env, {cell for cell, (room, _) in env.doors.items() if room in env.left})
    return explorer(env, cells_of(env, "$") if env.room in env.left else cells_of(env, "D"))


@pytest.mark.parametrize("seed", [0, 1])
def test_venture_winky_takes_treasures_from_new_rooms(seed):
    env, info = play(VENTURE, winky, seed, turns=1500)
    assert env.score.done >= 2 and env.episode_return >= 2 * env.params.unit - 1
    assert len(env.map.visited) >= 3


def test_venture_a_reckless_winky_loses_every_life():
    def reckless(env):
        h = min(env.foes, key=lambda f: abs(f.r - env.r) + abs(f.c - env.c))
        dr, dc = h.r - env.r, h.c - env.c
        return (DOWN if dr > 0 else UP) if abs(dr) >= abs(dc) else (RIGHT if dc > 0 else LEFT)
    env, info = play(VENTURE, reckless, 0, turns=2000)
    assert info["won"] is False and env.lives == 0 and env.episode_return == pytest.approx(-1.0)


def enter_room(env, room=(0, 0)):
    cell = next(cell for cell, (key, _) in env.doors.items() if key == room)
    env.r, env.c = cell[0] + 1, cell[1]          # below a door on a top box's bottom side
    assert env.still[cell[0]][cell[1]] == "D"
    env.foes[:] = []
    env.step(UP)
    assert env.room == room and env.map.hud().startswith("Map @")


def test_venture_a_door_leads_into_its_room_and_out_to_the_hallway():
    env = make(VENTURE)
    env.reset(seed=0)
    enter_room(env)
    assert env.still[env.r][env.c] == "." and any(f.glyph == "S" for f in env.foes)
    door = next(cell for cell in cells_of(env, "D") if cell[1] == env.params.width - 1)
    env.foes[:] = []
    env.r, env.c = door[0], door[1] - 1
    env.step(RIGHT)
    assert env.room == (1, 1) and env.map.hud() == "Map +-?/-@-/?-?"


def test_venture_arrows_slay_and_corpses_kill_and_slaying_pays_after_the_treasure():
    env = make(VENTURE)
    env.reset(seed=0)
    enter_room(env)
    env.foes[:] = []
    foe = env.add_foe(env.r, env.c - 2, glyph="S")
    env.face = (0, -1)
    env.step(FIRE)
    assert foe not in env.foes and env.corpses and env.episode_return == 0     # no treasure yet
    corpse = env.corpses[0]
    assert env.frame.grid[corpse.r][corpse.c] == CORPSE
    gold = next(iter(cells_of(env, "$")))
    env.r, env.c = gold[0], gold[1] + 1
    env.step(LEFT)
    assert env.episode_return == pytest.approx(env.params.unit) and env.room not in env.left
    foe = env.add_foe(env.r, env.c - 2, glyph="S")
    env.step(FIRE)
    assert env.episode_return == pytest.approx(env.params.unit + env.params.kill)
    env.r, env.c = env.corpses[-1].r, env.corpses[-1].c + 1
    lives = env.lives
    env.step(LEFT)
    assert env.lives == lives - 1


def test_venture_lingering_brings_a_hallmonster_in():
    env = make(VENTURE)
    env.reset(seed=0)
    enter_room(env)
    env.foes[:] = []
    lives = env.lives
    for _ in range(env.params.linger + 1):
        env.step(NOOP)
    assert env.prowler is not None and "H" in "".join(env.frame.grid)
    for _ in range(60):
        env.step(NOOP)
        if env.lives < lives:
            break
    assert env.lives == lives - 1 and env.prowler is None


def test_venture_four_treasures_start_a_new_level():
    env = make(VENTURE, goal=8)
    env.reset(seed=0)
    kinds = set()
    for room in sorted(env.boxes):
        env.go(room, 1, 1)
        kinds.add(env._kind(room))
        gold = next(iter(cells_of(env, "$")))
        env.foes[:] = []
        env._take(*gold, "$")
    door = next(iter(cells_of(env, "D")))
    env._cross(*door)
    assert env.level == 2 and env.room == (1, 1) and env.left == set(env.boxes)
    assert env.score.done == 4 and not env.done and env.map.visited == {(1, 1)}
    env.go((0, 0), 1, 1)
    assert env._kind((0, 0)) not in kinds and "$" in "".join(env.still)


# -- tutankham ----------------------------------------------------------------------------------------
TUT = "glyphbench/atari-tutankham-v0"


def explorer_of_the_tomb(env) -> int:
    """Loot this chamber, then head for the key's chamber (or, key in hand, the door's)."""
    here = env.room[1]
    loot = cells_of(env, "$") | (set() if env.key else cells_of(env, "k"))
    if loot:
        return explorer(env, loot)
    want = next((k for k, rows in enumerate(env.plan) if "k" in "".join(rows)), None)
    if env.key or want is None:
        want = env.params.chambers - 1
    if want == here:
        targets = cells_of(env, "D") if env.key else set()
    else:
        side = env.params.width - 1 if want > here else 0
        targets = {(r, c) for r, c in cells_of(env, "+") if c == side}
    return explorer(env, targets) if targets else explorer(env, set())


@pytest.mark.parametrize("seed", [0, 1])
def test_tutankham_explorer_loots_chambers_and_opens_the_door(seed):
    env, info = play(TUT, explorer_of_the_tomb, seed, turns=1500)
    assert env.score.done >= 3 and len(env.map.visited) >= 3 or env.zone > 1
    assert env.episode_return >= 3 * env.params.unit


def test_tutankham_a_still_explorer_is_hunted_down():
    env, info = play(TUT, lambda e: NOOP, 0, turns=3000)
    assert info["won"] is False and env.lives == 0 and env.episode_return == pytest.approx(-1.0)


def bare_chamber(seed=0):
    env = make(TUT)
    env.reset(seed=seed)
    env.foes[:] = []
    env.born = 10 ** 6                      # no creature comes out during the test
    return env


def test_tutankham_fires_sideways_only_and_the_clock_spends_the_gun():
    env = bare_chamber()
    env.step(UP)
    env.step(DOWN)                           # moved down, still aiming right (the start's aim)
    assert env.aim == (0, 1) and env.frame.grid[env.r][env.c] == ">"
    right = env.add_foe(env.r, env.c + 2, glyph="M")
    env.step(FIRE)
    assert right not in env.foes and env.episode_return == pytest.approx(40)
    assert env.frame.grid[env.r][env.c] == ">"
    env.clock.left = 1
    env.step(NOOP)
    assert env.clock.left == 0
    foe = env.add_foe(env.r, env.c + 2, glyph="B")
    env.step(FIRE)
    assert foe in env.foes and not env.gun.shots


def test_tutankham_the_flash_bomb_slays_the_screen_once_a_life():
    env = bare_chamber()
    for k in range(3):
        env.add_foe(13, 3 + 5 * k, glyph="SMB"[k])
    env.step(6)
    assert not env.foes and env.episode_return == pytest.approx(120) and env.flashes == 0
    env.add_foe(13, 5, glyph="S")
    env.step(6)
    assert len(env.foes) == 1                # none left this life
    env.lose_life("test")
    assert env.flashes == 1


def test_tutankham_the_key_opens_the_door_to_the_next_zone():
    env = bare_chamber()
    last = (0, env.params.chambers - 1)
    door = next((r, c) for r, row in enumerate(env.plan[last[1]]) for c, ch in enumerate(row) if ch == "D")
    env.go(last, door[0], door[1] - 1)
    env.foes[:] = []
    env.step(RIGHT)
    assert env.zone == 1 and env.room == last and env.score.done == 0       # locked
    env.key = True
    env.step(RIGHT)
    assert env.zone == 2 and env.room == (0, 0) and env.score.done == 1 and not env.key
    assert env.map.visited == {(0, 0)} and env.clock.left >= env.params.clock - 1


def test_tutankham_passages_join_neighbouring_chambers_and_creatures_come_from_nests():
    env = bare_chamber(1)
    passage = next((r, c) for r, c in cells_of(env, "+") if c == env.params.width - 1)
    env.r, env.c = passage[0], passage[1] - 1
    env.step(RIGHT)
    assert env.room == (0, 1) and (env.r, env.c) == (passage[0], 1) and env.map.hud().startswith("Map +@")
    nest = env.nests[1]
    for _ in range(env.params.spawn + 1):
        env.step(NOOP)
    assert env.foes and abs(env.foes[0].r - nest[0]) + abs(env.foes[0].c - nest[1]) <= 2
    assert env.foes[0].glyph == nest[2]


@pytest.mark.parametrize("seed", range(6))
def test_tutankham_every_zone_can_be_walked_from_its_entry_to_the_loot_key_and_door(seed):
    env = make(TUT)
    env.reset(seed=seed)
    for _ in range(3):
        tomb = ["".join(rows[r] for rows in env.plan) for r in range(env.params.height)]  # side by side
        reach = {(env.entry, 1)}
        queue = deque(reach)
        while queue:
            r, c = queue.popleft()
            for dr, dc in MOVE:
                cell = (r + dr, c + dc)
                if cell not in reach and 0 <= cell[1] < len(tomb[0]) and tomb[cell[0]][cell[1]] not in "#O":
                    reach.add(cell)
                    queue.append(cell)
        wanted = {(r, c) for r, row in enumerate(tomb) for c, ch in enumerate(row) if ch in "$kD"}
        assert len(wanted) == env.params.treasures + 2 and wanted <= reach
        for k, (r, c, _) in enumerate(env.nests):
            c += k * env.params.width
            assert tomb[r][c] == "O" and "." in (tomb[r - 1][c], tomb[r + 1][c])
        env.zone += 1
        env._zone()
