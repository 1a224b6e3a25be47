"""Full NetHack: NLE's NetHack Challenge game on the MiniHack tasks' wrapper and renderer.

The game is NLE's ``NetHackChallenge`` (``nle.env.tasks``): the whole dungeon, a character whose
role, race, gender and alignment NetHack picks at random (``character="@"``), no wizard mode,
and the score reward (the change of NetHack's in-game score, no penalties). Two settings differ
from the challenge, both for the one-reply-one-command turn of every GlyphBench task:

- seeds are set (the challenge forbids it, against seed hunting in a competition): NetHack's
  generators are seeded from the episode seed as in every NetHack task here, so the random
  character too is a function of the seed (different across seeds, the same for one seed);
- ``--More--`` and menus are handled inside the turn (``allow_all_modes=False``) and NetHack's
  questions are answered by the stated rules (``engine.ANSWER_RULES``), as in MiniHack.

Actions: NLE's full list (``nle.nethack.ACTIONS``) by name. The 22 names of the MiniHack set
keep their meaning (MOVE_N ..., WAIT, SEARCH, PICKUP, ..., ESCAPE); every other command is NLE's
``Command`` name; the three text characters that are also commands (``+ " $``) are aliases of
those commands (SEESPELLS, SEEAMULET, SEEGOLD), so each key has one name.
"""

from __future__ import annotations

import logging
import re
import warnings
from dataclasses import dataclass
from typing import Any

from ...core.actions import ActionSet
from ...core.params import param
from . import render
# (the engine first: without the nethack extra it raises the one-line MissingExtraError)
from .engine import ANSWER_RULES, COMMANDS, ESC, MOVE_DIRECTIONS, MOVES, RUNNING, _RAW_STEP_CAP, NetHackTask

from nle import nethack
from nle.env.base import NLE
from nle.env.tasks import NetHackChallenge

# one line each, ours; the MiniHack set's wording where a name is shared
_DESCRIPTIONS = {
    **{n: d for n, _, d in COMMANDS},
    "WIELD": "wield a weapon",
    "UP": "climb a staircase up (<) you stand on",
    "DOWN": "go down a staircase (>) you stand on",
    "MORE": "press Enter (no command on the map)",
    "EXTCMD": "start an extended command (# ...; typing is cancelled)",
    "EXTLIST": "list the extended commands",
    "ADJUST": "move an item to another inventory letter",
    "ANNOTATE": "name this level (typing is cancelled)",
    "ATTRIBUTES": "show your attributes",
    "AUTOPICKUP": "toggle autopickup",
    "CALL": "name a monster or object type (typing is cancelled)",
    "CAST": "cast a known spell",
    "CHAT": "talk to someone next to you",
    "CLOSE": "close a door",
    "CONDUCT": "list the conducts you kept",
    "DIP": "dip an item into something",
    "DROPTYPE": "drop items by type",
    "ENGRAVE": "engrave on the floor (typing is cancelled)",
    "ENHANCE": "show or advance weapon and spell skills",
    "FIGHT": "prefix: the next move attacks even where no monster is seen",
    "FIRE": "fire what is in your quiver",
    "FORCE": "force the lock of a box with your weapon",
    "GLANCE": "describe a map position",
    "HISTORY": "does nothing here",
    "INVENTTYPE": "list inventory items of one type",
    "INVOKE": "invoke an item's special power",
    "JUMP": "jump to a position",
    "KICK": "kick something (a door, a monster, an object)",
    "KNOWN": "list the object types identified",
    "KNOWNCLASS": "list identified types of one class",
    "LOOT": "open a box or bag on the floor",
    "MONSTER": "use your monster form's special ability",
    "MOVE": "prefix: the next move does not pick up or fight",
    "MOVEFAR": "prefix: the next move runs without picking up or fighting",
    "OFFER": "sacrifice a corpse on an altar",
    "OPEN": "open a door",
    "OPTIONS": "does nothing here (the options are fixed)",
    "OVERVIEW": "summary of the dungeon explored",
    "PAY": "pay a shopkeeper",
    "PUTON": "put on a ring or amulet",
    "QUIT": "give up: end the game",
    "QUIVER": "put an item in your quiver",
    "REDRAW": "redraw the screen",
    "REMOVE": "remove a ring or amulet",
    "RIDE": "mount or dismount a steed",
    "RUB": "rub a lamp or stone",
    "RUSH": "prefix: the next move rushes until something interesting",
    "RUSH2": "prefix: the next move runs until something interesting",
    "SAVE": "does nothing here (saving is off)",
    "SEEALL": "show the equipment in use",
    "SEEAMULET": "show the amulet worn",
    "SEEARMOR": "show the armour worn",
    "SEEGOLD": "count your gold",
    "SEERINGS": "show the rings worn",
    "SEESPELLS": "list known spells",
    "SEETOOLS": "show the tools in use",
    "SEETRAP": "name an adjacent trap",
    "SEEWEAPON": "show the weapon wielded",
    "SHELL": "shell escape (disabled)",
    "SIT": "sit down",
    "SWAP": "swap your wielded and second weapon",
    "TAKEOFF": "take off a piece of armour",
    "TAKEOFFALL": "take off all armour",
    "TELEPORT": "teleport at will (if you can)",
    "THROW": "throw an item",
    "TIP": "empty a container onto the floor",
    "TRAVEL": "walk to the staircase down (>) once seen",
    "TURN": "turn undead (knights, priests)",
    "TWOWEAPON": "toggle fighting with two weapons",
    "UNTRAP": "disarm a trap",
    "VERSION": "show compile options",
    "VERSIONSHORT": "show the version",
    "WEAR": "put on a piece of armour",
    "WHATDOES": "tell what a key does",
    "WHATIS": "identify a map symbol",
    "WIPE": "wipe your face",
    "MINUS": "type -",
    "SPACE": "type a space",
    "APOS": "type '",
}
_RENAMED = {"ESC": "ESCAPE"}                     # NLE name -> the MiniHack set's name
_ALIASES = {"PLUS": "SEESPELLS", "QUOTE": "SEEAMULET", "DOLLAR": "SEEGOLD"}


def _action_table() -> tuple[ActionSet, dict[str, int]]:
    """The ActionSet over ``nethack.ACTIONS`` and each name's key."""
    keys: dict[str, int] = {}
    lines: list[tuple[str, str]] = []
    far: list[str] = []
    digits: list[str] = []
    moves = {ord(k): (n, d) for n, k, d in MOVES}
    for a in nethack.ACTIONS:
        key, kind = int(a), type(a).__name__
        if key in keys.values():                # a text character that is also a command
            continue
        if kind == "CompassDirection":
            name, way = moves[key]
            lines.append((name, f"move one cell {way} (into a monster: attack it)"))
        elif kind == "CompassDirectionLonger":
            name = "FAR_" + a.name
            far.append(name)
        elif a.name.startswith("NUM_"):
            name = a.name
            digits.append(name)
        else:
            name = _RENAMED.get(a.name, a.name)
            lines.append((name, _DESCRIPTIONS[name]))
        keys[name] = key
    groups = [("run that way until something interesting is seen", far),
              ("type a digit: a count for the next command (NUM_2 then SEARCH searches twice)", digits)]
    return ActionSet(lines, groups=groups, aliases=_ALIASES, noop="WAIT"), keys


FULL_ACTIONS, FULL_KEYS = _action_table()
_WAITS_FOR_MORE = {"FIGHT", "MOVE", "MOVEFAR", "RUSH", "RUSH2"} | {f"NUM_{d}" for d in range(10)}
_STEPS = dict(MOVE_DIRECTIONS)
_STEPS.update({"FAR" + name[4:]: d for name, d in list(_STEPS.items())})   # MOVE_N -> FAR_N
# NetHack waiting inside a command for input that is no question (a map position, the name
# of an extended command)
_PENDING = re.compile(r"^(?:Where do you want|Pick an object|Pick a monster|#)")
ATTRIBUTES_KEY = int(nethack.Command.ATTRIBUTES)
# ^X: "You are a Gallant, a level 1 female human Knight.  You are lawful, on a mission ..."
_CHARACTER = re.compile(r"You are an? [^,]+, a level \d+ ([^.]+)\. +"
                        r"You are (?:\w+ )?(lawful|neutral|chaotic)")
_ENDS = {nethack.ASCENDED: "Ascended", nethack.ESCAPED: "Escaped the dungeon", nethack.QUIT: "Quit"}
_ENCUMBRANCE = ("", "Burdened", "Stressed", "Strained", "Overtaxed", "Overloaded")
_BL_SCORE, _BL_CAP = nethack.NLE_BL_SCORE, nethack.NLE_BL_CAP

# NLE's options, but the end of the game shows no disclosure windows (inventory, conduct ...)
_OPTIONS = tuple(o for o in nethack.NETHACKOPTIONS if not o.startswith("disclose")) + (
    "disclose:-i -a -v -g -c -o",)

FULL_ANSWER_RULES = ANSWER_RULES.replace(" WIELD picks the equipment you got most recently;", "") + (
    " A request to type text is cancelled, a menu other than pick-up is closed, and a question "
    "asking for a map position is cancelled, except TRAVEL's, which picks the staircase down.")


class _SeededChallenge(NetHackChallenge):
    """NLE's NetHack Challenge with its seeds settable again (see the module docstring)."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        for name in ("set_initial_seeds", "set_current_seeds", "get_current_seeds"):
            delattr(self.nethack, name)          # the challenge's refusals: back to the methods

    seed = NLE.seed


ROLES = ("arc", "bar", "cav", "hea", "kni", "mon", "pri", "rog", "ran", "sam", "tou", "val", "wiz")


@dataclass(frozen=True)
class NetHackFullParams:
    # "@": NetHack draws role, race, alignment and gender; a role ("val"): it draws the rest
    character: str = param("@", choices=("@",) + ROLES)


class NetHackFull(NetHackTask):
    """The whole game of NetHack, scored by NetHack's own score."""

    title = "NetHack, the full game"
    Params = NetHackFullParams
    ACTIONS = FULL_ACTIONS
    KEYS = FULL_KEYS
    rules = ("You play NetHack as {character}: descend the dungeon, survive, and raise your score "
             "(experience, gold, depth reached; ascending with the Amulet of Yendor wins). The grid "
             "is the part of the current level seen so far; monsters move when you act; walking "
             "into a monster attacks it. " + FULL_ANSWER_RULES)
    rewards = ("each turn, the change of NetHack's score (the HUD's Score): deeper levels, "
               "experience, gold and more raise it; no other reward.")
    ends = "when the game ends (death, quitting, leaving the dungeon, ascension)"
    default_max_turns = 10_000

    def prompt_fields(self) -> dict[str, Any]:
        c = self.params.character
        return {"character": "a character NetHack picks at random (the HUD names it)"
                if c == "@" else f"a {c} (NetHack's role abbreviation; the HUD names the character)"}

    def _new_env(self) -> NLE:
        # NLE logs a warning for the 'internal' array: it is ours (is NetHack asking?), never shown
        nle_log = logging.getLogger("nle.env.base")
        level = nle_log.level
        nle_log.setLevel(logging.ERROR)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                return self._challenge()
            finally:
                nle_log.setLevel(level)

    def _challenge(self) -> NLE:
        return _SeededChallenge(
            character=self.params.character, observation_keys=(
                "glyphs", "chars", "screen_descriptions", "blstats", "message", "inv_letters",
                "inv_strs", "inv_oclasses", "tty_chars", "internal"),
            allow_all_modes=False, max_episode_steps=_RAW_STEP_CAP,
            no_progress_timeout=_RAW_STEP_CAP, fix_moon_phase=True, options=_OPTIONS)

    def _setup(self, rng) -> None:
        super()._setup(rng)
        self.character = self._read_character()
        self._level = self._where()

    def _where(self) -> tuple[int, int]:
        b = self.obs("blstats")
        return int(b[nethack.NLE_BL_DNUM]), int(b[nethack.NLE_BL_DLEVEL])

    def _build_frame(self):
        if self.status == RUNNING and self._where() != self._level:
            self._level = self._where()          # another level: the grid shows what is seen of it
            self.painter.view = render.MapView()   # (the painter draws its view)
            self.painter.view.see(self.obs("chars"))
        return super()._build_frame()

    def _read_character(self) -> str:
        """``lawful female human Knight``: NetHack's own account of the character (its ^X
        screen, which takes no game time), as the welcome message may have scrolled away."""
        nh = self.env.nethack
        obs, done = nh.step(ATTRIBUTES_KEY)
        screen = " ".join(render.text(row) for row in obs[self._ix["tty_chars"]])
        for _ in range(8):
            if done or not obs[self._ix["internal"]][3]:
                break
            obs, done = nh.step(ESC)
        m = _CHARACTER.search(screen)
        return f"{m.group(2)} {m.group(1)}" if m else self.params.character

    def _command(self, name: str) -> None:
        self._press(self.KEYS[name])
        if name in _WAITS_FOR_MORE:              # NetHack waits for the next key and says nothing:
            self._heard.clear()                  # what is on the message line is old
            return
        if name in _STEPS:
            self._last_move = _STEPS[name]
        if self.status or not self._heard or not _PENDING.match(self._heard[-1]):
            return
        self._heard.pop()                        # the prompt itself says nothing to the player
        if name == "TRAVEL":
            self._press(ord(">"))               # the cursor to the staircase down, if seen ...
            if not self._heard or not self._heard[-1].startswith("Can't find"):
                self._press(ord("."))           # ... and go
                return
        self._press(ESC)

    def _score(self) -> None:
        if self.status != RUNNING:
            self.finish(self.env.nethack.how_done() == nethack.ASCENDED)

    def _hud(self) -> str:
        if self.status != RUNNING:
            how = self.env.nethack.how_done()   # DIED, CHOKING, ... GENOCIDED: kinds of death
            return "Dead" if int(how) < int(nethack.PANICKED) else _ENDS.get(how, "Game over")
        b = self.obs("blstats").tolist()
        head = (f"{self.character} | Dlvl {b[render.BL_DEPTH]} ${b[render.BL_GOLD]} "
                f"Pw {b[render.BL_ENERGY]}/{b[render.BL_ENERGYMAX]} Xp {b[render.BL_XP]} "
                f"T {b[render.BL_TIME]} Score {b[_BL_SCORE]}")
        if 0 < b[_BL_CAP] < len(_ENCUMBRANCE):
            head += " " + _ENCUMBRANCE[b[_BL_CAP]]
        return head + " " + super()._hud()
