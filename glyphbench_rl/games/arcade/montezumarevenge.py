"""Montezuma's Revenge: Panama Joe explores a pyramid of 24 rooms (3, 5, 7 and 9 rooms a level,
seen one room at a time, the rooms visited mapped in the HUD). Kept from the original: rooms of
floors, ledges and ladders, ladders through floors and ceilings to the rooms below and above,
exits at the side walls to the next room of a level, ropes to leap onto over wide fire pits,
fire pits, floors that vanish over fire, blinking laser gates, rolling skulls, snakes and
spiders that kill on touch, swords that kill the monster they meet, coloured keys that each open
one door of their colour, jewels, a jump arc, deadly falls from a ledge, five lives and the
native points (key 100, door 300, jewel 1000; a sword is scored as a key, and a kill pays
nothing: our choice). The pyramid is made
from the seed: a random tree of links between neighbouring rooms, the doors on some side links
and each door's key in a room reachable before it, so there is always a way through. A room is
cleared when its treasures are taken and its doors opened; clearing ``goal`` rooms wins
(pattern D: losing the last life pays ``death``)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .engine import EMPTY, ArcadeParams, register_atari
from .platform import (DOWN, JUMP, JUMP_LEFT, JUMP_RIGHT, JUMP_TEXT, LADDER, LEFT, RIGHT, ROPE,
                       STAY, UP, Blink, Platformer, Walker, locks, paint, room_grid,
                       spanning_tree)
from .rooms import LEGEND, RoomMap

LAYOUT = ("---###---", "--#####--", "-#######-", "#########")
START = (0, 4)
WALL, FLOOR, FIRE, LASER, JEWEL, SWORD, YOU = "#", "=", "^", "!", "*", "/", "@"
KEYS, DOORS, COLOURS = "rbgy", "RBGY", ("red", "blue", "green", "yellow")
FOES = {"skull": "S", "snake": "s", "spider": "X"}
KINDS = ("fire", "rope", "laser", "bridge", "skull", "snake", "spider")
KEY_PTS, DOOR_PTS, JEWEL_PTS = 100, 300, 1000
PAY = {JEWEL: JEWEL_PTS, SWORD: KEY_PTS, **{k: KEY_PTS for k in KEYS}}
ACTIONS = ActionSet([("NOOP", "stand still (or hang on)"), ("FIRE", "jump straight up"),
                     ("UP", "climb up a ladder or rope"), ("RIGHT", "walk right"),
                     ("LEFT", "walk left"), ("DOWN", "climb down a ladder or rope"),
                     ("UP_RIGHT", "jump to the right"), ("UP_LEFT", "jump to the left")], noop="NOOP")
INTENTS = (STAY, JUMP, UP, RIGHT, LEFT, DOWN, JUMP_RIGHT, JUMP_LEFT)


@dataclass(frozen=True)
class MontezumaParams(ArcadeParams):
    width: int = param(20, 20, 40)
    height: int = param(11, 11, 20)
    lives: int = param(5, 1, 9)
    goal: int = param(24, 1, 24)
    unit: float = param(0.0, 0, 1000)
    death: float = param(-1.0, -10000, 0)
    doors: int = param(4, 0, 4)          # locked doors (each of its own colour)
    pace: int = param(2, 1, 8)           # a skull rolls a cell every this many ticks
    laser: int = param(6, 1, 30)         # a laser gate is on this many ticks, then off as long
    bridge: int = param(8, 7, 30)        # a vanishing floor is there this many ticks, then gone as long
    swords: float = param(0.25, 0, 1)    # chance a room holds a sword
    fall: int = param(3, 1, 8)           # rows you may fall and live


class Montezuma(Platformer):
    title = "Montezuma's Revenge"
    rules = ("A pyramid of {rooms} rooms, {width}x{height} each, seen one room at a time. " + LEGEND + ". "
             "You (@) walk on floors (=), climb ladders (H) and ropes (|), and leave a room through a "
             "gap in its side wall (#) or by a ladder through its floor or ceiling. " + JUMP_TEXT + "; "
             "a jump that meets a rope grabs it. Falling more than {fall} rows, fire (^), a lit laser "
             "gate (!, on {laser} ticks then off {laser}), fire under a vanishing floor (there {bridge} "
             "ticks, then gone {bridge}) and skulls (S), snakes (s) and spiders (X) each cost a "
             "life; you have {lives_text} and start again where you entered the room. A sword (/) "
             "kills the next monster you touch, and is used up. "
             "A key (r, b, g, y) opens one door of its colour (R, B, G, Y: walk into it holding the key). "
             "A room is cleared when its keys, swords and jewels (*) are taken and its doors opened. "
             "The HUD's Items are the keys and swords you carry.")
    rewards = ("+{key_pts} a key or a sword, +{door_pts} a door opened, +{jewel_pts} a jewel{room_text}; {death:g} "
               "when your last life is lost.")
    ends = "when you have cleared {goal} rooms, or you lose your last life"
    ACTIONS = ACTIONS
    Params = MontezumaParams
    pattern = "D"
    glyphs = {EMPTY: "air", WALL: "wall", FLOOR: "floor", LADDER: "ladder", ROPE: "rope",
              FIRE: "fire", LASER: "laser", JEWEL: "jewel", SWORD: "sword", **{k: f"{n} key" for k, n in zip(KEYS, COLOURS)},
              **{d: f"{n} door" for d, n in zip(DOORS, COLOURS)}, "S": "skull", "s": "snake",
              "X": "spider", YOU: "you"}
    SOLID = frozenset(WALL + FLOOR + DOORS)
    HAZARD = frozenset(FIRE + LASER)

    def prompt_fields(self) -> dict:
        unit = self.params.unit
        return {**super().prompt_fields(), "room_text": f", +{unit:g} a room cleared" if unit else "",
                "rooms": "".join(LAYOUT).count("#"), "key_pts": KEY_PTS, "door_pts": DOOR_PTS,
                "jewel_pts": JEWEL_PTS}

    def _setup(self, rng) -> None:
        p = self.params
        self.safe_fall = p.fall
        self.map = RoomMap(LAYOUT)
        rooms = self.map.rooms
        near = {a: [b for b in ((a[0], a[1] - 1), (a[0], a[1] + 1), (a[0] - 1, a[1]), (a[0] + 1, a[1]))
                    if b in rooms] for a in rooms}
        tree = spanning_tree(near, START, rng)
        sides = list(range(2, 6)) + list(range(p.width - 6, p.width - 2))
        self.plan = {room: {"items": [], "doors": [], "top": None, "bottom": None, "exits": set()} for room in sorted(rooms)}
        for a, b in tree:
            if a[0] == b[0]:
                self.plan[a]["exits"].add(b[1] - a[1])
                self.plan[b]["exits"].add(a[1] - b[1])
            else:
                up, down = (a, b) if a[0] < b[0] else (b, a)
                self.plan[up]["bottom"] = self.plan[down]["top"] = sides[int(rng.integers(len(sides)))]
        side = [e for e in tree if e[0][0] == e[1][0]]
        doors = [side[int(i)] for i in rng.choice(len(side), min(p.doors, len(side)), replace=False)]
        for k, (inner, outer, keyroom) in enumerate(locks(tree, START, doors, rng)):
            self.plan[inner]["doors"].append((outer[1] - inner[1], DOORS[k]))
            self.plan[keyroom]["items"].append(KEYS[k])
        for room, s in self.plan.items():
            if not s["items"]:
                s["items"].append(JEWEL)
            if room != START and rng.random() < p.swords:
                s["items"].append(SWORD)
            free = [c for c in sides if c not in (s["top"], s["bottom"])]
            picks = [free[int(i)] for i in rng.permutation(len(free))]
            s["ledge"] = picks.pop() if rng.random() < 0.6 else None
            if room == START:
                self.start_col = picks.pop(0)
            s["spots"] = picks
            s["kind"] = "skull" if room == START else KINDS[int(rng.integers(len(KINDS)))]
            s["left"] = len(s["items"]) + len(s["doors"])
        self.start(rng)
        self.items, self._items_text = "", None
        self._enter(START, p.height - 2, self.start_col)

    def _build(self, room) -> list[str]:
        """The still rows of a room, made on the first visit."""
        p, s = self.params, self.plan[room]
        w, h, mid = p.width, p.height, p.width // 2
        g = room_grid(h, w, WALL, FLOOR, s["exits"], 4, s["top"], s["bottom"])
        for dc, door in s["doors"]:
            paint(g, door, range(h - 4, h - 1), (1 if dc < 0 else w - 2,))
        items, spots = list(s["items"]), list(s["spots"])
        lc = s["ledge"]
        if lc is not None:
            span = range(1, 7) if lc < mid else range(w - 7, w - 1)
            paint(g, FLOOR, (h - 6,), span)
            paint(g, LADDER, range(h - 6, h - 1), (lc,))
            on = [c for c in spots if c in span]
            if on:
                g[h - 7][on[0]] = items.pop()
                spots.remove(on[0])
        for item, c in zip(items, spots):
            g[h - 2][c] = item
        if s["top"] is not None:               # (through a ledge in its way)
            paint(g, LADDER, range(h - 1), (s["top"],))
        if s["kind"] == "fire":
            paint(g, FIRE, (h - 1,), (mid - 1, mid))
        elif s["kind"] == "rope":
            paint(g, FIRE, (h - 1,), range(mid - 2, mid + 3))
            paint(g, ROPE, range(2, h - 2), (mid,))
        return ["".join(row) for row in g]

    def _enter(self, room, r: int, c: int) -> None:
        p, s = self.params, self.plan[room]
        self.room = room
        self.map.enter(*room)
        self.show(room)
        self.entry = (r, c)
        self.place(r, c)
        mid, low = p.width // 2, p.height - 2
        kind = s["kind"]
        self.foes = [] if s.get("slain") else ([Walker(low, mid - 3, mid - 3, mid + 2, p.pace if kind == "skull" else 1, FOES[kind])]
                     if kind in ("skull", "spider") else [Walker(low, mid, mid, mid, 0, "s")] if kind == "snake" else [])
        self.blinks = ([Blink([(rr, mid) for rr in range(p.height - 5, p.height - 1)], LASER, EMPTY, p.laser, p.laser)]
                       if kind == "laser" else
                       [Blink([(p.height - 1, c) for c in range(mid - 2, mid + 3)], FLOOR, FIRE, p.bridge, p.bridge)]
                       if kind == "bridge" else [])
        self.blink(self.blinks)

    def _respawn(self) -> None:
        self.place(*self.entry)

    def _leave(self, dr: int, dc: int) -> None:
        self._enter(*self.cross(self.room, dr, dc))

    def _bump(self, r: int, c: int, ch: str) -> bool:
        key = ch.lower()
        if ch in DOORS and key in self.items:
            self.items = self.items.replace(key, "", 1)
            for rr in range(self.params.height - 4, self.params.height - 1):
                self.set_still(rr, c, EMPTY)
            self.say(f"The {COLOURS[DOORS.index(ch)]} door opens.")
            self.score.bonus(DOOR_PTS)
            self._took()
            return True
        return False

    def _took(self) -> None:
        s = self.plan[self.room]
        s["left"] -= 1
        if s["left"] == 0:
            self._clear()

    def _clear(self) -> None:
        self.say("Room cleared!")
        self.score.gain()

    def _play(self, action: int) -> None:
        if self.blinks:
            self.blink(self.blinks)
        if not self.walk(INTENTS[action]) or self.done:
            return
        ch = self.still[self.r][self.c]
        if ch in PAY:
            self.set_still(self.r, self.c, EMPTY)
            if ch in KEYS or ch == SWORD:
                self.items += ch
            if ch in KEYS:
                self.say(f"A {COLOURS[KEYS.index(ch)]} key.")
            self.score.bonus(PAY[ch])
            self._took()
            if self.done:
                return
        foe = self.meet(self.foes)
        if foe is not None:
            name = {"S": "skull", "s": "snake", "X": "spider"}[foe.glyph]
            if SWORD in self.items:
                self.items = self.items.replace(SWORD, "", 1)
                self.foes.remove(foe)
                self.plan[self.room]["slain"] = True
                self.say(f"Your sword kills the {name}.")
            else:
                self.lose_life(f"A {name} got you.")

    def _hazard_text(self) -> str:
        return "You burned."

    def _sprites(self):
        out = [(f.r, f.c, f.glyph) for f in self.foes]
        out.append((self.r, self.c, YOU))
        return out

    def _extra_hud(self) -> str:
        text = self._items_text
        if text is None or text[0] != self.items or text[1] != self.map.hud():
            text = self._items_text = (self.items, self.map.hud(), f"Items {self.items or '-'} | {self.map.hud()}")
        return text[2]


register_atari(Montezuma, "montezumarevenge", max_turns=10000)
