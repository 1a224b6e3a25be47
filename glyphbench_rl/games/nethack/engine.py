"""NetHack and MiniHack tasks on the real NetHack engine (``nle``, ``minihack``).

Imported only by the registry when one of these tasks is made (see ``games/nethack/__init__``).

One model reply is one turn: an action name is one NetHack command, and whatever NetHack asks
back within it is answered here by fixed rules the system prompt states (``ANSWER_RULES``):
``--More--`` is dismissed (its text kept for the message line), a yes/no question gets yes, an
item question gets the last item letter NetHack offers (usually the item got most recently), a
direction question points at the nearest monster in view, else the nearest door, else the way
you last moved, and a pick-up menu takes everything. A turn counts as one turn even when
NetHack's clock does not move.

Seeds: NetHack's core, display and level-generation generators are seeded from the episode's
SeedSequence (``core.seeding.nle_seeds``), with reseeding off and the moon phase derived from
the seed, so the same seed and actions give the same episode in any process.
"""

from __future__ import annotations

import importlib
import re
import warnings
import weakref
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from ...core.actions import ActionSet
from ...core.params import param
from ...core.registry import MissingExtraError
from ...core.seeding import nle_seeds
from ...core.task import GlyphTask
from . import render
from .levels import LEVELS

try:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from nle import nethack
        from nle.env.base import NLE
        from nle.env.tasks import NetHackStaircase
        import minihack  # noqa: F401  (registers MiniHack's gymnasium IDs)
        from minihack.reward_manager import MessageEvent, RewardManager
        import gymnasium as gym
except ImportError as e:   # pragma: no cover - depends on the installed extras
    raise MissingExtraError(
        f"the MiniHack and NetHack tasks need the 'nethack' extra ({e}): "
        f"pip install 'glyphbench_rl[nethack]'") from None
from .lean import lean, turn_function   # noqa: E402  (needs minihack)

# NLE's StepStatus values (int compares: the enum's members cost an attribute search a turn)
DEATH, RUNNING = int(NLE.StepStatus.DEATH), int(NLE.StepStatus.RUNNING)
SUCCESS = int(NetHackStaircase.StepStatus.TASK_SUCCESSFUL)

ESC, ENTER, SPACE = 27, 13, 32
PRAY_KEY = 0x80 | ord("p")          # M-p, NetHack's #pray
_RAW_STEP_CAP = 10**7               # NetHack's own step cap: we end episodes ourselves

MOVES = (("MOVE_N", "k", "north"), ("MOVE_S", "j", "south"), ("MOVE_E", "l", "east"), ("MOVE_W", "h", "west"),
         ("MOVE_NE", "u", "north-east"), ("MOVE_NW", "y", "north-west"), ("MOVE_SE", "n", "south-east"),
         ("MOVE_SW", "b", "south-west"))
DIRECTION_KEYS = {(0, -1): "k", (0, 1): "j", (1, 0): "l", (-1, 0): "h", (1, -1): "u", (-1, -1): "y",
                  (1, 1): "n", (-1, 1): "b"}
MOVE_DIRECTIONS = {n: next(d for d, key in DIRECTION_KEYS.items() if key == k) for n, k, _ in MOVES}
COMMANDS = (
    ("WAIT", ".", "rest one turn"),
    ("SEARCH", "s", "search the cells around you for hidden doors and traps"),
    ("LOOK", ":", "look at what is on your cell"),
    ("PICKUP", ",", "pick up everything on your cell"),
    ("DROP", "d", "drop an item"),
    ("EAT", "e", "eat food here or carried"),
    ("READ", "r", "read a scroll or spellbook"),
    ("QUAFF", "q", "drink a potion, or from a fountain or sink you stand on"),
    ("WIELD", "w", "equip an item: wield a weapon, wear armour, or put on a ring or amulet"),
    ("ZAP", "z", "zap a wand"),
    ("PRAY", PRAY_KEY, "pray to your god"),
    ("APPLY", "a", "use a tool (a key unlocks a door, a horn is blown)"),
    ("INVENTORY", "i", "list what you carry"),
    ("ESCAPE", ESC, "cancel whatever NetHack is asking"),
)
# the eight moves share one prompt line (every action a group, so the indices keep this order)
ACTION_GROUPS = ([("move one cell that way (N is up); into a monster: attack it", [n for n, _, _ in MOVES])]
                 + [(d, [n]) for n, _, d in COMMANDS])
ACTIONS = ActionSet(groups=ACTION_GROUPS, noop="WAIT")
KEYS = {n: (k if isinstance(k, int) else ord(k)) for n, k, _ in MOVES + tuple((n, k, d) for n, k, d in COMMANDS)}

ANSWER_RULES = (
    "When an action makes NetHack ask something, it is answered in the same turn: a yes/no "
    "question gets yes; a question about which item gets the last item letter NetHack offers "
    "(usually the item you got most recently); a direction question points at the nearest "
    "monster in view, else the nearest door, else the way you last moved; WIELD picks the "
    "equipment you got most recently; a pick-up menu takes everything.")

# object classes of NetHack (objclass.h) that WIELD equips, and the command for each
_EQUIP = {2: "w", 3: "W", 4: "P", 5: "P"}          # weapon, armour, ring, amulet
_ITEM_QUESTION = re.compile(r"\[([^\]]*)\]")
_DEATH_CAUSE = re.compile(r"\b(?:killed|drowned|burned|choked|starved|petrified|dissolved|crushed|"
                          r"died|turned to stone|zapped (?:him|her)self)\b[^.,;:!]*?(?=\s{2,}|[.,;:!]|$)")


class NetHackTask(GlyphTask):
    """A GlyphTask over one NLE environment, created at the first reset and reused."""

    ACTIONS = ACTIONS
    KEYS = KEYS                  # action name -> NetHack key (a task with other actions brings its own)
    extra_chars = render.SPARE + render.BLANK + "".join(render.PREFERRED.values())
    default_max_turns = 512
    terse_items = False        # inventory names only (no letters), without blessed/uncursed,
                               # enchantment or weapon slots

    # -- the environment ------------------------------------------------------------------------
    def _new_env(self) -> NLE:
        raise NotImplementedError

    def _before_reset(self, rng: np.random.Generator) -> None:
        """Per-episode changes to the environment before NetHack starts (a new level file)."""

    def _init(self) -> None:
        self.env: NLE | None = None
        self.glyph_map = render.Glyphs()

    def _open(self) -> NLE:
        env = self._new_env()
        # records --More-- texts (see _known_steps); through a weak reference, so that the env
        # does not keep its task alive: a task nobody holds is freed at once, its NetHack with it
        task = weakref.ref(self)
        env._perform_known_steps = lambda obs, done, exceptions=True: task()._known_steps(obs, done, exceptions)
        # a won episode stays in the game (so its last frame shows the level, not the end
        # screens); the next reset starts a new game all the same
        env._quit_game = lambda observation, done: None
        self._turn = turn_function(env)                # env.step without the dicts we do not read
        self._index = {int(a): i for i, a in enumerate(env.actions)}
        keys = env._observation_keys
        self._ix = {k: keys.index(k) for k in ("chars", "glyphs", "screen_descriptions", "blstats",
                                               "message", "inv_letters", "inv_strs", "inv_oclasses",
                                               "tty_chars", "internal")}
        return env

    def close(self) -> None:
        if self.env is not None:
            self.env.close()
            self.env = None

    def raw_replay(self):
        """The benchmark's raw step: upstream's environment on the keys of this task's turns."""
        from .rawstep import RawReplay
        return RawReplay(self)

    def obs(self, key: str) -> np.ndarray:
        """NLE's current array ``key`` (``chars``, ``blstats``, ``message`` ...)."""
        return self.env.last_observation[self._ix[key]]

    # -- GlyphTask hooks ------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        if self.env is None:
            self.env = self._open()
        core, disp, lgen = nle_seeds(self.seed_sequence)
        self._before_reset(rng)
        self.env.seed(core, disp, False, lgen)
        self._heard: list[str] = []
        self._pick_all = False
        self._death: str | None = None
        self._ended = False                   # NetHack's end screens began
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            self.env.reset()
        self.status = 0                       # NLE/MiniHack StepStatus of the last command
        self._last_move = (1, 0)
        self.glyph_map = render.Glyphs()
        self.painter = render.Painter(self.glyph_map, _VARYING)
        self._inv = ((b"", b""), "")
        self._note_message()
        self._messages = self._heard

    def vocab(self):
        return self.glyph_map.vocab

    def _act(self, action: int) -> None:
        name = self.actions[action].name
        self._heard = []
        self._pick_all = name == "PICKUP"
        self._command(name)
        for _ in range(8):                      # answer what NetHack asks, by the stated rules
            if self.status or not self._asking():
                break
            self._press(self._answer(self._question()))
        else:
            while not self.status and self._asking():
                self._press(ESC)
        self._messages.extend(self._heard)
        self._score()

    def _command(self, name: str) -> None:
        """Press the keys of action ``name`` (what NetHack asks back is answered after)."""
        key = self._equip_key() if name == "WIELD" else None
        if key is not None:
            self._press(key[0])
            self._press(key[1])
        else:
            self._press(self.KEYS[name])
        if name in MOVE_DIRECTIONS:
            self._last_move = MOVE_DIRECTIONS[name]

    def _score(self) -> None:
        """Turn NetHack's end of episode into ours: MiniHack's reward was added by ``_press``."""
        if self.status == DEATH:
            self.say(f"You die, {self._death}." if self._death else "You die.")
            self.reward(self.params.reward_lose)
            self.finish(False)
        elif self.status != RUNNING:
            # MiniHack ends a task on a paying event of either sign (Memento's squeaky board is
            # TASK_SUCCESSFUL with -1): won means the episode ended paying more than nothing
            self.finish(self.status == SUCCESS and self.episode_return + self._step_reward > 0)

    def _grid(self) -> list[str]:
        if self.status == DEATH:   # NetHack shows its end screens now
            return list(self._frame.grid)
        return self.painter.rows()

    def _hud(self) -> str:
        if self.status == DEATH:
            return "Dead"
        hud = render.status(self.obs("blstats"))
        if self.view.scrolled(self._bounds):
            y0, y1, x0, x1 = self._bounds
            hud += f" | View cols {x0}-{x1 - 1} rows {y0}-{y1 - 1} of 79x21"
        letters, strs = self.obs("inv_letters"), self.obs("inv_strs")
        key = (letters.tobytes(), strs.tobytes())     # (the inventory text only when they change)
        if key != self._inv[0]:
            inv = render.inventory(letters, strs, self.terse_items)
            names = (v for _, v in inv) if self.terse_items else (f"{k} {v}" for k, v in inv)
            self._inv = key, " | Inv " + ", ".join(names) if inv else ""
        return hud + self._inv[1]

    def _build_frame(self):
        if self.status != DEATH:   # what is shown: before the HUD and grid
            self._bounds = self.painter.update(self.obs("chars"), self.obs("glyphs"),
                                               self.obs("screen_descriptions"), self.hero)
        return super()._build_frame()

    @property
    def view(self) -> render.MapView:
        """What part of the map is shown (the painter's)."""
        return self.painter.view

    # -- talking to NetHack --------------------------------------------------------------------
    @property
    def hero(self) -> tuple[int, int]:
        b = self.obs("blstats")
        return int(b[render.BL_X]), int(b[render.BL_Y])

    def _press(self, key: int) -> None:
        _, gain, done, _, status = self._turn(self._index[key])
        self.reward(gain)
        if done:
            self.status = int(status)
        if not self._asking() and not self._ended:
            self._note_message()

    def _asking(self) -> bool:
        return bool(self.obs("internal")[1])

    def _question(self) -> str:
        return render.text(self.obs("message"))

    def _note_message(self) -> None:
        self._hear(render.text(self.obs("message")))

    def _hear(self, msg: str) -> None:
        """Keep a message for this turn's message line (NetHack repeats one across keys)."""
        if msg and (not self._heard or self._heard[-1] != msg):
            self._heard.append(msg)

    def _known_steps(self, observation, done, exceptions=True):
        """NLE's own handling of --More--, text input and (at the end) questions, but keeping
        what each --More-- said, and taking everything from a pick-up menu."""
        env = self.env
        for _ in range(64):                                   # (NetHack never asks this often)
            if done:
                break
            internal = observation[env._internal_index]
            if internal[3]:                                   # --More-- or a menu window
                self._message_events(observation)
                key = self._window(observation)
                observation, done = env.nethack.step(key)
                continue
            if internal[2]:                                   # text input: we never type any
                observation, done = env.nethack.step(ESC)
                continue
            if internal[1] and not exceptions:               # a question while quitting
                observation, done = env.nethack.step(ESC)
            break
        return observation, done

    def _message_events(self, observation) -> None:
        """Upstream's message events (a kill, "This scroll seems to be blank.") read only the
        message a command ends on; one shown before a --More-- ("You kill the minotaur!" before
        "The death ray bounces!") would be lost for good, so it is checked here too."""
        manager = getattr(self.env, "reward_manager", None)
        if type(manager) is not RewardManager:                # (ordered or grouped ones: as upstream)
            return
        for event in manager.events:
            if isinstance(event, MessageEvent) and not event.achieved:
                manager._reward += event.check(self.env, None, None, observation)

    def _window(self, observation) -> int:
        msg = render.text(observation[self._ix["message"]])
        if observation[self.env._program_state_index][0]:   # the game is over: its last messages
            if not self._death:                               # are kept, its end screens (dump,
                screen = " ".join(render.text(row) for row in observation[self._ix["tty_chars"]])
                found = _DEATH_CAUSE.search(msg + " " + screen)   # tombstone) only for the cause
                self._death = found.group(0).strip() if found else ""
            if not msg:
                self._ended = True
            if not self._ended:
                self._hear(msg)
            return ENTER
        if msg:
            self._hear(msg)
            return ENTER
        tty = observation[self._ix["tty_chars"]]
        top = next((row for row in tty if (row != SPACE).any()), None)
        col = int(np.argmax(top != SPACE)) if top is not None else 0   # a window over the map
        lines = [render.text(row[col:]) for row in tty]                # starts where its title does
        lines = [s for s in lines if s]
        head = lines[0] if lines else ""
        if head.startswith("Pick up what?"):
            if self._pick_all:
                self._pick_all = False
                return ord(".")                               # select every item ...
            return ENTER                                      # ... and take them
        if not any(s.endswith("--More--") for s in lines):
            return ESC                                        # a menu (the inventory): close it
        if head.endswith(":"):                                # "Things that are here:" ...
            end = next(i for i, s in enumerate(lines) if s.endswith("--More--"))
            items = lines[1:end][:8]
            self._heard.append(head + " " + ", ".join(items) + ".")
        return ENTER

    def _answer(self, question: str) -> int:
        if "direction" in question:
            return ord(DIRECTION_KEYS[self._direction()])
        m = _ITEM_QUESTION.search(question)
        if m is None:
            return ESC
        options = m.group(1)
        if options.startswith("yn"):
            return ord("y")
        offered = _letters(options.split(" or ")[0])
        return ord(offered[-1]) if offered else ESC

    def _direction(self) -> tuple[int, int]:
        """Toward the nearest monster in view, else the nearest door, else the last move."""
        hx, hy = self.hero
        glyphs = self.obs("glyphs")
        monsters = np.argwhere(glyphs < nethack.GLYPH_INVIS_OFF)
        targets = [(int(x), int(y)) for y, x in monsters if (x, y) != (hx, hy)]
        if not targets:
            doors = np.argwhere(np.isin(glyphs, _DOOR_GLYPHS))
            targets = [(int(x), int(y)) for y, x in doors]
        if not targets:
            return self._last_move
        x, y = min(targets, key=lambda t: (max(abs(t[0] - hx), abs(t[1] - hy)), t[1], t[0]))
        return (int(np.sign(x - hx)), int(np.sign(y - hy))) if (x, y) != (hx, hy) else self._last_move

    def _equip_key(self) -> tuple[int, int] | None:
        """WIELD: the command and letter that equip the newest weapon, armour, ring or amulet
        not already in use, or None (then NetHack's wield question is answered as usual)."""
        letters = self.obs("inv_letters").tolist()
        classes = self.obs("inv_oclasses").tolist()
        strs = self.obs("inv_strs")
        best = None
        for i, letter in enumerate(letters):
            if not letter:
                break
            cls = classes[i]
            if cls in _EQUIP and not re.search(r"\((?:weapon in|being worn|on (?:left|right))", render.text(strs[i])):
                best = (ord(_EQUIP[cls]), letter)
        return best


def _letters(spec: str) -> list[str]:
    """Inventory letters of a NetHack offer like ``- abf`` or ``a-d``."""
    out: list[str] = []
    s = spec.replace(" ", "")
    i = 0
    while i < len(s):
        if i + 2 < len(s) and s[i + 1] == "-" and s[i].isalpha() and s[i + 2].isalpha():
            out.extend(chr(c) for c in range(ord(s[i]), ord(s[i + 2]) + 1))
            i += 3
        else:
            if s[i].isalpha():
                out.append(s[i])
            i += 1
    return out


_DOOR_GLYPHS = np.array([nethack.GLYPH_CMAP_OFF + i for i in range(12, 17)])   # S_ndoor (doorway)..S_hcdoor

# glyphs whose screen description can differ from cell to cell or turn to turn (the renderer looks
# again every turn): monsters, objects, warnings and statues, and of the map features doorways
# ("broken door"), altars (their alignment) and traps ("trapped door"); see NetHack's lookat()
_VARYING = np.zeros(nethack.MAX_GLYPH, bool)
_VARYING[:nethack.GLYPH_CMAP_OFF] = True
_VARYING[nethack.GLYPH_WARNING_OFF:] = True
_VARYING[[nethack.GLYPH_CMAP_OFF + 12, nethack.GLYPH_CMAP_OFF + 27]] = True   # S_ndoor, S_altar
_VARYING[[g for g in range(nethack.GLYPH_CMAP_OFF, nethack.GLYPH_EXPLODE_OFF) if nethack.glyph_is_trap(g)]] = True


# -- MiniHack -------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MiniHackParams:
    level: str = param("room-5x5", choices=tuple(LEVELS))
    reward_win: float = param(1.0, 0.0, 1.0)
    reward_lose: float = param(-1.0, -1.0, 0.0)


class MiniHackTask(NetHackTask):
    """One MiniHack level: upstream's own task (des file, reward events, end condition) or one
    of ours (``levels.LEVELS``), on the real NetHack engine."""

    title = "MiniHack, a task on the real NetHack game"
    terse_items = True         # (no action here names a letter, swaps, fires or takes off)
    Params = MiniHackParams
    rules = ("{goal} You play NetHack: the grid is the part of the level seen so far (" + render.BLANK
             + " unknown: not seen, dark or solid rock); monsters "
             "move when you act; walking into a monster attacks it. " + ANSWER_RULES)
    plain_rewards = "{reward_win:+g} when the goal is reached{lose_text}; no other reward."
    ends = "when the goal is reached{lose_end}"

    def _make_actions(self) -> ActionSet:
        only = LEVELS[self.params.level].actions
        if not only:
            return ACTIONS
        groups = [(d, [n for n in names if n in only]) for d, names in ACTION_GROUPS]
        return ActionSet(groups=[(d, names) for d, names in groups if names])

    @property
    def rewards(self) -> str:   # type: ignore[override]
        return LEVELS[self.params.level].rewards or self.plain_rewards

    def _before_reset(self, rng: np.random.Generator) -> None:
        next_level = getattr(self.env, "next_level", None)   # a level generated per episode
        if next_level is not None:
            next_level(rng)

    def prompt_fields(self) -> dict[str, Any]:
        level = LEVELS[self.params.level]
        lose = f", {self.params.reward_lose:+g} if {level.lose}" if level.lose else ""
        return {"goal": level.goal, "reward_win": self.params.reward_win, "lose_text": lose,
                "lose_end": f" or {level.lose}" if level.lose else ""}

    def _new_env(self) -> NLE:
        level = LEVELS[self.params.level]
        kwargs: dict[str, Any] = dict(
            observation_keys=("blstats",), actions=nethack.ACTIONS, allow_all_yn_questions=True,
            allow_all_modes=False, max_episode_steps=_RAW_STEP_CAP, penalty_step=0.0, penalty_time=0.0,
            reward_win=self.params.reward_win, reward_lose=0.0, fix_moon_phase=True)
        if ":" in level.source:
            module, _, fn = level.source.partition(":")
            builder: Callable[[], tuple[type, dict]] = getattr(importlib.import_module(module), fn)
            cls, extra = builder()
            kwargs.update(extra)
        else:
            cls = gym.spec(level.source).entry_point
            module, _, name = cls.partition(":")
            cls = getattr(importlib.import_module(module), name)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return lean(cls)(**kwargs)          # (upstream's class, copying less a step: lean.py)
