"""Enduro: an endurance race on a road of lanes that scrolls down at your own speed. Slower cars
ride with the road; change lanes to overtake them (a car that drops behind you counts). A
collision stops your car (speed 0); on the MiniAtari preset it also costs one of a few lives
(pattern A: credit per overtake, no penalty). As on the Atari, the day is a clock: at nightfall
the race is over, lost unless the cars are passed.
Balance: the day clock (without one a random driver, never out of time, passed every car)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Pacer, Strip, put_one

PLAYER, CAR, EDGE = "A", "C", "|"
ACTIONS = ActionSet([("NOOP", "keep your speed and lane"), ("LEFT", "change to the lane on the left"),
                     ("RIGHT", "change to the lane on the right"), ("ACCELERATE", "speed up by one"),
                     ("BRAKE", "slow down by one")], noop="NOOP")
LEFT, RIGHT, ACCEL, BRAKE = 1, 2, 3, 4


@dataclass(frozen=True)
class EnduroParams(ArcadeParams):
    height: int = param(9, 6, 40)
    lives: int = param(2, 1, 9)
    goal: int = param(10, 1, 1000)         # cars to overtake
    unit: float = param(0.1, 0, 100)
    death: float = param(0.0, 0, 0)
    lanes: int = param(3, 2, 8)
    top: int = param(3, 1, 6)              # top speed: the road moves a row every top+1-speed turns
    spacing: int = param(3, 2, 12)         # rows between cars
    pair: float = param(0.0, 0, 1)         # chance a second car shares a row
    wreck: int = param(1, 0, 1)            # 1: a collision costs a life; 0: only your speed
    day: int = param(60, 0, 100000)        # turns until nightfall ends the race (0: no clock)


HUD_TEXT: dict[tuple, str] = {}   # the HUD note by its values


class Enduro(ArcadeTask):
    title = "Enduro"
    rules = ("You drive the car (A) near the bottom of a road with {lanes} lanes (columns {lane_cols}). "
             "Speed goes from 0 to {top}: at speed s the road scrolls down one row every {top1} - s "
             "turns; at 0 the other cars pull away one row every {top1} turns. Slower cars (C) come {spacing} rows apart; overtake them by "
             "changing lanes. A car that drops behind you counts as overtaken. A collision "
             "stops your car{wreck_text}.")
    rewards = "+{unit} for each car overtaken."
    ends = "when you have overtaken {goal} cars{ends_text}"
    ACTIONS = ACTIONS
    Params = EnduroParams
    pattern = "A"
    glyphs = {EMPTY: "road", EDGE: "road edge", CAR: "other car", PLAYER: "you (your car)"}

    def prompt_fields(self) -> dict:
        p = self.params
        wreck = f" and costs a life ({p.lives} in all)" if p.wreck else ""
        return {**super().prompt_fields(), "lane_cols": ", ".join(str(c) for c in self._cols()),
                "top1": p.top + 1, "wreck_text": wreck,
                "ends_text": (", or you have no lives left" if p.wreck else "")
                + (f", or night falls after {p.day} turns (lost unless the cars are passed)" if p.day else "")}

    def _cols(self) -> list[int]:
        return [2 + 3 * k for k in range(self.params.lanes)]

    def _still(self) -> list[str]:
        w = 3 * self.params.lanes + 3
        return [EDGE + EMPTY * (w - 2) + EDGE] * self.params.height

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.cols, self.blank = self._cols(), self.still[0]
        self.strip = Strip(self.still, "down")
        self.lane, self.speed, self.car_r = p.lanes // 2, 0, p.height - 2
        self.pacer, self.since = Pacer(0), 0
        self.strip.preroll(p.height - 3, self._line)

    def _line(self) -> str:
        p = self.params
        self.since += 1
        if self.since < p.spacing:
            return self.blank
        self.since = 0
        k = self.draws.below(p.lanes)
        line = put_one(self.blank, self.cols[k], CAR)
        if p.pair and self.draws.random() < p.pair:
            line = put_one(line, self.cols[(k + 1 + self.draws.below(p.lanes - 1)) % p.lanes], CAR)
        return line

    def _play(self, action: int) -> None:
        self._drive(action)
        day = self.params.day
        if day and self.tick >= day and not self.done:
            self.say("Night falls: the race is over.")
            self.finish(won=False)

    def _drive(self, action: int) -> None:
        p = self.params
        if action == ACCEL:
            self.speed = min(p.top, self.speed + 1)
        elif action == BRAKE:
            self.speed = max(0, self.speed - 1)
        elif action in (LEFT, RIGHT):
            self.lane = min(p.lanes - 1, max(0, self.lane + (-1 if action == LEFT else 1)))
        if self._collided():
            return
        self.pacer.period = p.top + 1 - self.speed if self.speed else 0
        if not self.speed and self.tick % (p.top + 1) == 0:     # stopped: the others pull away
            self.strip.rows = self.strip.rows[1:] + [self.blank]
        elif self.pacer.due(self.tick):
            gone = self.strip.scroll(self._line())
            passed = gone.count(CAR)
            if passed:
                self.score.gain(passed)
                self.say("Overtaken!")
            if not self.done:
                self._collided()

    def _collided(self) -> bool:
        c = self.cols[self.lane]
        if self.strip.get(self.car_r, c) != CAR:
            return False
        self.strip.put(self.car_r, c, EMPTY)
        self.speed = 0
        if self.params.wreck:
            self.lose_life("You crashed!")
        else:
            self.say("You crashed! Speed 0.")
        return True

    def _rows(self) -> list[str]:
        return self.strip.rows[:]

    def _sprites(self):
        return ((self.car_r, self.cols[self.lane], PLAYER),)

    def _extra_hud(self) -> str:
        key = (self.speed, self.params.day and self.params.day - self.tick)
        hud = HUD_TEXT.get(key)
        if hud is None:   # (made once per value: the values recur from episode to episode)
            if len(HUD_TEXT) >= 4096:
                HUD_TEXT.clear()
            hud = f"Speed {self.speed}"
            if self.params.day:
                hud += f" | Nightfall in {self.params.day - self.tick}"
            HUD_TEXT[key] = hud
        return hud


register_arcade(Enduro, "enduro",
                mini=dict(max_turns=300),
                atari=dict(height=20, lives=1, goal=200, unit=1.0, top=4, spacing=3, pair=0.3,
                           wreck=0, day=2000, max_turns=10000))
