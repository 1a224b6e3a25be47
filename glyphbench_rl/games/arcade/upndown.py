"""Up'n Down: a buggy drives up a road that scrolls down past it, picking up flags (F) while
oncoming cars (C) drive down at it. JUMP leaps for a few turns: cars pass beneath, and landing on
one crushes it. Meeting a car on the ground, or leaving the road on the Atari preset (its banks
wander), wrecks the buggy (pattern D; the MiniAtari preset pays no death penalty)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Body
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Channel, Pacer, Strip, banks_fit, put_one

BUGGY, AIR, CAR, FLAG, BANK = "A", "^", "C", "F", "#"
ACTIONS = ActionSet([("NOOP", "keep going"), ("UP", "move one row up the screen"),
                     ("DOWN", "move one row down the screen"), ("LEFT", "steer one cell left"),
                     ("RIGHT", "steer one cell right"), ("JUMP", "leap over what is ahead")],
                    noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
JUMP = 5


@dataclass(frozen=True)
class UpParams(ArcadeParams):
    width: int = param(12, 8, 40)
    height: int = param(9, 6, 40)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 100)
    death: float = param(0.0, -1, 0)
    narrow: int = param(6, 3, 30)          # the road's narrowest and widest span
    wide: int = param(6, 3, 30)
    every: int = param(2, 1, 6)            # turns per scroll
    car_every: int = param(2, 1, 6)        # turns per row an oncoming car drives
    spawn: int = param(4, 1, 30)           # turns between oncoming cars
    flag_every: int = param(4, 2, 20)      # rows between flags
    air: int = param(2, 1, 6)              # turns a jump lasts
    crush: int = param(0, 0, 1)            # 1: a crushed car counts like a flag

    check = banks_fit


class UpNDown(ArcadeTask):
    title = "Up'n Down"
    rules = ("You drive the buggy (A) up a road {road_text} on a {width}x{height} view, with "
             "{lives_text}; the road scrolls down one row every {every} turns and you may move "
             "within the lower half. Collect flags (F) by driving over them. Oncoming cars (C) "
             "enter at the top every {spawn} turns and drive down a row every {car_every} turns. "
             "JUMP keeps you in the air (^) for {air} turns: cars pass beneath, and landing on one "
             "crushes it{crush_text}. A car meeting you on the ground{bank_text} wrecks the buggy.")
    rewards = "+{unit} for each flag{crush_reward}{death_text}."
    ends = "when you have scored {goal} times or the game is lost"
    ACTIONS = ACTIONS
    Params = UpParams
    pattern = "D"
    glyphs = {EMPTY: "road", BANK: "roadside", FLAG: "flag", CAR: "oncoming car",
              BUGGY: "you (on the road)", AIR: "you (in the air)"}

    def prompt_fields(self) -> dict:
        p = self.params
        road = f"{p.wide} cells wide" if p.narrow == p.wide else f"{p.narrow} to {p.wide} cells wide"
        return {**super().prompt_fields(), "road_text": road,
                "crush_text": " (it counts like a flag)" if p.crush else "",
                "crush_reward": " and each car crushed" if p.crush else "",
                "bank_text": ", or leaving the road (#)," if p.narrow < p.wide else "",
                "death_text": f"; {p.death} when the game is lost" if p.death else ""}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.channel = Channel(p.width, p.narrow, p.wide)
        self.strip = Strip([self.channel.line(BANK)] * p.height, "down")
        self.r, self.col = p.height - 2, p.width // 2
        self.cars: list[Body] = []
        self.pacer, self.since, self.landing = Pacer(p.every), 0, 0
        self.strip.preroll(p.height - 3, self._line)

    def _line(self) -> str:
        p = self.params
        left, right, line = self.channel.step(self.draws, BANK)
        self.since += 1
        if self.since >= p.flag_every:
            self.since = 0
            line = put_one(line, left + self.draws.below(right - left + 1), FLAG)
        return line

    def _play(self, action: int) -> None:
        p = self.params
        dr, dc = MOVES[action]
        r, c = self.r + dr, self.col + dc
        top, bottom = p.height // 2, p.height - 1
        self.r = top if r < top else r if r < bottom else bottom
        self.col = 0 if c < 0 else c if c < p.width else p.width - 1
        if action == JUMP and self.tick > self.landing:
            self.landing = self.tick + p.air
        scroll = self.pacer.due(self.tick)
        if scroll:
            self.strip.scroll(self._line())
        drive = self.tick % p.car_every == 0
        step, gone, h = scroll + drive, False, p.height
        if step:
            for car in self.cars:
                car.data, car.r = car.r, car.r + step
                gone = gone or car.r >= h
        else:
            for car in self.cars:
                car.data = car.r
        if gone:
            self.cars = [car for car in self.cars if car.r < p.height]
        if self.tick % p.spawn == 0:
            left, right = self.channel.left, self.channel.right
            self.cars.append(Body(0, left + self.draws.below(right - left + 1), glyph=CAR, data=0))
        self._meet()

    def _meet(self) -> None:
        p = self.params
        here = self.strip.rows[self.r][self.col]
        if here == FLAG:
            self.strip.put(self.r, self.col, EMPTY)
            self.score.gain()
            self.say("Flag!")
            if self.done:
                return
        up = self.tick < self.landing
        for car in self.cars:                     # met if it came down through your row
            if car.c == self.col and car.data <= self.r <= car.r:
                if up:
                    continue
                if self.tick == self.landing:
                    self.cars.remove(car)
                    self.say("Crushed a car!")
                    if p.crush:
                        self.score.gain()
                    return
                self.lose_life("A car hit you!")
                return
        if here == BANK and not up:
            self.lose_life("You left the road!")

    def _respawn(self) -> None:
        self.cars = [car for car in self.cars if car.r < self.params.height // 2 - 1]
        row = self.strip.rows[self.r]
        self.col = (row.find(EMPTY) + row.rfind(EMPTY)) // 2 if EMPTY in row else self.col
        self.landing = 0

    def _grid(self) -> list[str]:
        rows = self.strip.rows[:]
        self._grids += 1
        drawn = self._drawn   # (each row remembered: see ``_draw``)
        for car in self.cars:                  # (cars drive on the road, inside the view)
            r = car.r
            key = (rows[r], car.c, CAR)
            rows[r] = drawn.get(key) or self._draw(key)
        r = self.r
        key = (rows[r], self.col, AIR if self.tick < self.landing else BUGGY)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows


register_arcade(UpNDown, "upndown",
                mini=dict(max_turns=300),
                atari=dict(width=16, height=20, lives=3, goal=50, unit=1.0, death=-1.0, narrow=5,
                           wide=10, every=1, car_every=2, spawn=3, flag_every=5, crush=1,
                           max_turns=10000))
