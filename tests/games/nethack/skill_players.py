"""Scripted players for the MiniHack skill tasks (eat, pray, read, sink, wield, wand of death).

They see only what the agent sees: the grid, the legend's meanings, the HUD's inventory and the
message line; they act with the task's action names and rely on the answer rules the system
prompt states (yes to yes/no, the newest item, a direction toward the nearest monster).
"""

from __future__ import annotations

from collections import deque

STEPS = {(0, -1): "MOVE_N", (0, 1): "MOVE_S", (1, 0): "MOVE_E", (-1, 0): "MOVE_W",
         (1, -1): "MOVE_NE", (-1, -1): "MOVE_NW", (1, 1): "MOVE_SE", (-1, 1): "MOVE_SW"}
# map features one can stand on
_FEATURES = ("floor", "dark floor", "doorway", "altar", "sink", "stairs", "corridor", "door", "fountain")
# what is neither walkable nor a monster
_SCENERY = ("wall", "unknown", "tree", "water", "lava", "iron bars", "cloud", "boulder")
UNSEEN = "unknown"
# an object on the floor is named without an article ("scroll", "zinc wand", "2 apples") and its
# grid character may be a spare one (NetHack's "?" taken by another scroll): the player knows it by
# a count or a noun of its name, those of NetHack's unidentified appearances and of the objects
# these levels hold
_OBJECT_WORDS = frozenset(
    "scroll scrolls wand wands potion potions ring rings amulet amulets spellbook spellbooks gem gems "
    "stone stones rock rocks corpse corpses apple apples egg eggs ration rations food tin tins "
    "dagger daggers knife sword axe mace club spear bow arrow arrows dart darts sling "
    "mail armor helmet shield boots gloves cloak robe coins".split())
ZAP_RANGE = 7             # a wand's ray flies 7 to 13 cells: within 7 it always reaches
SAFE_BOUNCE = 6           # a ray that bounces off a wall this far away cannot fly back to you


# -- reading the frame --------------------------------------------------------------------------
def is_item(meaning: str) -> bool:
    """An object on the floor (a count, or an object noun in its name)."""
    return meaning[:1].isdigit() or not _OBJECT_WORDS.isdisjoint(meaning.split())


def walkable(meaning: str) -> bool:
    return is_item(meaning) or any(w in meaning for w in _FEATURES)


def is_monster(meaning: str) -> bool:
    return meaning != "you" and not walkable(meaning) and not any(w in meaning for w in _SCENERY)


def cells(frame, test) -> list[tuple[int, int]]:
    """Grid cells (x, y) whose legend meaning passes ``test``."""
    chars = {g for g, m in frame.legend if test(m)}
    return [(x, y) for y, row in enumerate(frame.grid) for x, c in enumerate(row) if c in chars]


def hero(frame) -> tuple[int, int]:
    (pos,) = cells(frame, lambda m: m == "you")
    return pos


def meaning_at(frame, x: int, y: int) -> str:
    if 0 <= y < len(frame.grid) and 0 <= x < len(frame.grid[y]):
        return dict(frame.legend)[frame.grid[y][x]]
    return UNSEEN


def inventory(frame) -> list[tuple[str, str]]:
    """``(slot, name)`` pairs of the HUD's inventory, in its order (newest last); the HUD shows no
    letters, so a slot is the item's position."""
    part = next((p[4:] for p in frame.hud.split(" | ") if p.startswith("Inv ")), "")
    return [(str(i), name) for i, name in enumerate(part.split(", ")) if name]


def monsters(frame) -> list[tuple[int, int]]:
    return cells(frame, is_monster)


def adjacent_monster(frame) -> tuple[int, int] | None:
    hx, hy = hero(frame)
    return next(((x, y) for x, y in monsters(frame) if max(abs(x - hx), abs(y - hy)) == 1), None)


def nearest(spots, me: tuple[int, int]) -> tuple[int, int]:
    return min(spots, key=lambda c: (max(abs(c[0] - me[0]), abs(c[1] - me[1])), c[1], c[0]))


def path_step(frame, goals) -> str | None:
    """The first move of a shortest path from the hero to the nearest of ``goals`` over walkable
    cells (a goal itself may be a monster: moving into it attacks), or None when there is none."""
    goals = set(goals)
    meaning = dict(frame.legend)
    grid = frame.grid
    start = hero(frame)
    first = {start: None}
    todo = deque([start])
    while todo:
        x, y = todo.popleft()
        if (x, y) in goals and (x, y) != start:
            return first[(x, y)]
        for (dx, dy), name in STEPS.items():
            nx, ny = x + dx, y + dy
            if (nx, ny) in first or not (0 <= ny < len(grid) and 0 <= nx < len(grid[ny])):
                continue
            if (nx, ny) not in goals and not walkable(meaning[grid[ny][nx]]):
                continue
            if dx and dy and any("door" in meaning[grid[cy][cx]] for cx, cy in ((x, y), (nx, ny))):
                continue     # NetHack forbids diagonal moves into or out of a doorway
            first[(nx, ny)] = first[(x, y)] or name
            todo.append((nx, ny))
    return None


def frontier(frame) -> list[tuple[int, int]]:
    """Walkable cells next to cells not seen yet (or the edge of what is shown)."""
    return [(x, y) for x, y in cells(frame, walkable)
            if any(UNSEEN in meaning_at(frame, x + dx, y + dy) for dx, dy in STEPS if not (dx and dy))]


# -- playing ----------------------------------------------------------------------------------
def fight(task) -> bool:
    """Attack a monster next to you (a lichen would hold you, anything else bites)."""
    foe = adjacent_monster(task.frame)
    if foe is None:
        return False
    hx, hy = hero(task.frame)
    task.step(STEPS[(foe[0] - hx, foe[1] - hy)])
    return True


def walk_onto(task, word: str, limit: int = 50) -> bool:
    """Walk onto the nearest cell whose legend meaning names ``word``; True once there."""
    f = task.frame
    seen = cells(f, lambda m: word in m and m != "you")
    if not seen:
        return False
    spot = nearest(seen, hero(f))
    for _ in range(limit):
        if task.done or hero(task.frame) == spot:
            break
        task.step(path_step(task.frame, [spot]) or "WAIT")
    return hero(task.frame) == spot


def use_in_place(task, word: str, verb: str, limit: int = 200) -> None:
    """Walk onto the feature or object whose legend meaning names ``word`` and ``verb`` there
    (EAT an apple on the floor, PRAY on an altar, QUAFF on a sink), killing monsters that come
    next to you first. A target under the hero is known from the message line (LOOK)."""
    here = word in task.frame.message and "here" in task.frame.message
    spot = hero(task.frame) if here else None
    for _ in range(limit):
        if task.done:
            return
        if fight(task):
            continue
        f = task.frame
        me = hero(f)
        if spot is not None and me == spot:
            task.step(verb)
            if not task.done:
                task.step("LOOK")           # something else was used first: is the target still here?
                if word not in task.frame.message:
                    spot = None
            continue
        seen = cells(f, lambda m: word in m and m != "you")
        if seen:
            spot = nearest(seen, me)
        step = path_step(f, [spot]) if spot is not None else None
        task.step(step or "WAIT")


def carry_and_use(task, word: str, verb: str, limit: int = 200) -> None:
    """PICKUP the object whose meaning names ``word``, DROP whatever else came with it (the
    answer rules give the newest item to DROP and to ``verb``), then ``verb`` it (READ, WIELD)."""
    kit = len(inventory(task.frame))          # the starting kit
    here = word in task.frame.message and "here" in task.frame.message
    spot = hero(task.frame) if here else None
    for _ in range(limit):
        if task.done:
            return
        if fight(task):
            continue
        got = inventory(task.frame)[kit:]
        if got and word not in got[-1][1]:
            task.step("DROP")
            continue
        if got:
            task.step(verb)
            continue
        f = task.frame
        me = hero(f)
        if spot is not None and me == spot:
            task.step("PICKUP")
            spot = None
            continue
        seen = cells(f, lambda m: word in m and is_item(m))
        if seen:
            spot = nearest(seen, me)
        step = path_step(f, [spot]) if spot is not None else None
        task.step(step or "WAIT")


def zap_line(frame, foe) -> bool:
    """Is ``foe`` on a straight line within sure reach, with nothing but floor between, and the
    wall behind it far enough that the bouncing ray cannot come back to you?"""
    hx, hy = hero(frame)
    dx, dy = foe[0] - hx, foe[1] - hy
    dist = max(abs(dx), abs(dy))
    if not (dx == 0 or dy == 0 or abs(dx) == abs(dy)) or not 0 < dist <= ZAP_RANGE:
        return False
    ux, uy = (dx > 0) - (dx < 0), (dy > 0) - (dy < 0)
    if any(not walkable(meaning_at(frame, hx + ux * k, hy + uy * k)) for k in range(1, dist)):
        return False
    room = dist
    while walkable(meaning_at(frame, hx + ux * (room + 1), hy + uy * (room + 1))):
        room += 1
    return room >= SAFE_BOUNCE or dist <= 2      # (next to you it kills you anyway)


def wand_of_death(task, limit: int = 600) -> None:
    """Find and PICKUP the wand, ZAP it at the minotaur once it is in line, then walk to the
    staircase down (exploring what is not seen yet)."""
    for _ in range(limit):
        if task.done:
            return
        f = task.frame
        armed = any("wand" in name for _, name in inventory(f))
        foes = monsters(f)
        if armed and any(zap_line(f, foe) for foe in foes):
            task.step("ZAP")
            continue
        if not armed:
            if "wand" in f.message and "here" in f.message:
                task.step("PICKUP")
                continue
            targets = cells(f, lambda m: "wand" in m and is_item(m))
        else:
            targets = cells(f, lambda m: "stairs down" in m)
        step = path_step(f, targets) if targets else None
        if step is None and armed and foes:
            step = path_step(f, foes)           # it blocks the way: go closer until it is in line
        if step is None:
            step = path_step(f, frontier(f))
        task.step(step or "WAIT")
