"""GlyphTask: the gymnasium environment every game derives from.

The invariants of the task contract are enforced here, once:
turn cap and truncation, return clamp for standard tasks, forfeit turns, refusal of steps after
the end, rewards accumulated (never overwritten) within a step, and the system prompt composed
from the game's rules template, its parameters and its ActionSet.

A game supplies: ``title``, ``rules``/``rewards``/``ends`` templates (formatted with the game's
parameters), a ``Params`` dataclass whose fields declare their ranges (``core.params.param``;
checked here, once), a glyph vocabulary ``glyphs`` (legend order), an ActionSet, and four hooks:
``_setup(rng)``, ``_act(action)``, ``_grid()`` and ``_hud()``. Inside ``_act`` the game reports
outcomes with ``self.reward(x)``, ``self.finish(won)`` and ``self.say(text)``.

Randomness: ``_setup`` gets the episode's one generator. Rules that want their own stream (so
that adding a draw to one rule does not shift every other) take ``self.stream("mobs")``: a
generator derived from the episode's SeedSequence and the name, the same object for the whole
episode, independent of the main generator. Wrappers over engines with their own generators
seed them from ``self.seed_sequence`` (``seeding.nle_seeds``, ``seeding.jax_key_data``).
"""

from __future__ import annotations

import dataclasses
import secrets
import string
from typing import Any, ClassVar, Mapping

import gymnasium as gym
import numpy as np

from .actions import ActionSet
from .frame import Frame, legend_line, legends_for, new_frame, render, vocab_entries
from .params import ParamError, check_params
from .seeding import MAX_SEED, check_seed, derive

STANDARD_TURN_CAP = 512
_RETURN_EPS = 1e-9

OBSERVATION_CONVENTIONS = (
    "Each turn you see a status line (Step t/N and other counters), the grid (one character per "
    "cell, north at the top), a legend of the glyphs on the grid, and a message line when "
    "something happened or the turn paid a reward (Reward +x or Reward -x).")
AXES_CONVENTION = "Columns are lettered from A at the left and rows numbered from 1 at the top; a cell is named like C4."
ACTION_FORMAT = "Reply with exactly one action from the list as <action>NAME</action>."


class EpisodeEnded(RuntimeError):
    """A step was asked of an episode that has already terminated or been truncated."""


@dataclasses.dataclass(frozen=True)
class NoParams:
    pass


class GlyphTask(gym.Env[str, int]):
    metadata: ClassVar[dict] = {"render_modes": ["ansi"], "render_fps": 4}

    # -- declared by each game ----------------------------------------------------------------
    title: ClassVar[str] = ""
    rules: ClassVar[str] = ""       # how the game works; str.format template over prompt_fields()
    rewards: ClassVar[str] = ""     # how reward is earned and lost; same template fields
    ends: ClassVar[str] = ""        # "when ..." clause for termination, or "" if only the cap ends it
    Params: ClassVar[type] = NoParams
    ACTIONS: ClassVar[ActionSet | None] = None
    glyphs: ClassVar[Mapping[str, str]] = {}   # legend vocabulary, in legend order
    extra_chars: ClassVar[str] = ""            # non-ASCII characters used in HUD or messages
    axes: ClassVar[bool] = False
    default_max_turns: ClassVar[int] = 100

    _plain_vocab: ClassVar[bool] = True   # the class keeps GlyphTask.vocab (its glyphs)
    _plain_frame: ClassVar[bool] = True   # it keeps GlyphTask._build_frame, with no axes
    _own_bits: ClassVar[bool] = False     # it overrides _glyph_bits

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        cls._plain_vocab = cls.vocab is GlyphTask.vocab
        cls._plain_frame = cls._build_frame is GlyphTask._build_frame and not cls.axes
        cls._own_bits = cls._glyph_bits is not GlyphTask._glyph_bits

    def __init__(self, *, max_turns: int | None = None, tier: str = "standard",
                 task_id: str | None = None, render_mode: str | None = None, **params: Any) -> None:
        self.task_id = task_id or type(self).__name__
        self.tier = tier
        self.params = self._make_params(params)
        self.max_turns = self.default_max_turns if max_turns is None else max_turns
        if isinstance(self.max_turns, bool) or not isinstance(self.max_turns, int) or self.max_turns < 1:
            raise ValueError(f"{self.task_id}: max_turns must be a positive int, got {self.max_turns!r}")
        if tier == "standard" and self.max_turns > STANDARD_TURN_CAP:
            raise ValueError(f"{self.task_id}: standard tasks end by {STANDARD_TURN_CAP} turns, "
                             f"max_turns={self.max_turns}")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']}, got {render_mode!r}")
        self.render_mode = render_mode
        self._init()
        self.actions: ActionSet = self._make_actions()
        self.action_space = gym.spaces.Discrete(len(self.actions))
        self._n_actions = len(self.actions)
        chars = set(string.printable) - set("\t\r\x0b\x0c") | set(self.extra_chars)
        chars.update("".join(self.vocab()))
        self.observation_space = gym.spaces.Text(max_length=200_000, min_length=1,
                                                 charset=frozenset(chars))
        self._seedseq: np.random.SeedSequence | None = None
        self._streams: dict[tuple, np.random.Generator] = {}
        self._started = False
        # the vocabulary the legend is drawn from, its shared memo of rows' glyphs, and the last
        # frame's glyphs (as the memo's bits), legend and legend line
        self._legend_vocab: Mapping[str, str] | None = None
        self._legend_memo = legends_for(())
        self._legend_bits = -1
        self._legend: tuple[tuple[str, str], ...] = ()
        self._legend_text = legend_line(())
        self._reset_counters()

    # -- hooks for games -------------------------------------------------------------------------
    def _init(self) -> None:
        """Derive per-instance constants from ``self.params`` (runs once, before the actions)."""

    def _make_actions(self) -> ActionSet:
        if self.ACTIONS is None:
            raise NotImplementedError(f"{type(self).__name__} declares no ACTIONS")
        return self.ACTIONS

    def vocab(self) -> Mapping[str, str]:
        """Glyph -> meaning for every glyph this instance can draw, in legend order. Return the
        same mapping while it holds (the legend of the last frame is reused while the grid
        shows the same glyphs) and a new one to change it, never the old one changed in place."""
        return self.glyphs

    def prompt_fields(self) -> dict[str, Any]:
        """Values the rules/rewards/ends templates may name (parameters plus derived values)."""
        return dataclasses.asdict(self.params)

    def _setup(self, rng: np.random.Generator) -> None:
        raise NotImplementedError

    def _act(self, action: int) -> None:
        raise NotImplementedError

    def _grid(self) -> list[str]:
        raise NotImplementedError

    def _hud(self) -> str:
        return ""

    def _glyph_bits(self, legends) -> int | None:
        """The legend of the grid ``_grid`` just drew, as ``legends`` (a ``frame.Legends``) would
        find it from the rows (a bit per entry of ``legends.entries`` whose glyph is on the
        grid), when the game knows it without reading the rows; None to have the rows read.
        (A game whose grid is drawn from codes can collect them as it draws.)"""
        return None

    # -- called by games inside _act ------------------------------------------------------------
    def reward(self, amount: float) -> None:
        """Add to this step's reward (penalties and progress in one step add up)."""
        self._step_reward += amount

    def finish(self, won: bool | None = None) -> None:
        """End the episode this step (terminated); ``won`` is reported in info."""
        self._terminated = self.done = True
        self.won = won

    def say(self, text: str) -> None:
        self._messages.append(text)

    def stream(self, name: str, *keys: int | str) -> np.random.Generator:
        """This episode's random stream called ``name`` (and ``keys``): a deterministic function
        of the episode's SeedSequence and the names, the same generator on every call within
        the episode, and independent of the generator ``_setup`` got (drawing from it changes
        nothing there)."""
        if not isinstance(name, str):
            raise TypeError(f"a stream is named by a string first, got {name!r}")
        if self._seedseq is None:
            raise RuntimeError(f"{self.task_id}: call reset(seed=...) before using a stream")
        key = (name, *keys)
        gen = self._streams.get(key)
        if gen is None:
            gen = self._streams[key] = np.random.Generator(np.random.PCG64(derive(self._seedseq, *key)))
        return gen

    @property
    def seed_sequence(self) -> np.random.SeedSequence:
        """The episode's SeedSequence, for seeding external engines (``core.seeding``)."""
        if self._seedseq is None:
            raise RuntimeError(f"{self.task_id}: call reset(seed=...) first")
        return self._seedseq

    def time_bonus(self, weight: float) -> float:
        """1 minus ``weight`` x the share of the horizon used so far: the usual win reward of
        puzzles that pay for finishing early."""
        return 1 - weight * self.turn / self.max_turns

    # -- gymnasium API ------------------------------------------------------------------------------
    def reset(self, *, seed: int | None = None, options: dict | None = None) -> tuple[str, dict]:
        if seed is None and self._seedseq is None:
            seed = secrets.randbelow(MAX_SEED + 1)   # gymnasium convention: drawn from entropy
        if seed is None:
            # gymnasium convention: an unseeded reset continues the seeded stream, reproducibly
            self._seedseq = self._seedseq.spawn(1)[0]
            self.seed_value: int | None = None
        else:
            self.seed_value = check_seed(seed)
            self._seedseq = np.random.SeedSequence(self.seed_value)
        rng = np.random.Generator(np.random.PCG64(self._seedseq))
        self._np_random = rng
        self._np_random_seed = self.seed_value if self.seed_value is not None else -1
        self._streams = {}
        self._reset_counters()
        self._setup(rng)
        self._started = True
        self._frame = self._build_frame()
        return self._frame.render(), self._info(forfeit=False) | {"seed": self.seed_value}

    def step(self, action: int | str) -> tuple[str, float, bool, bool, dict]:
        if self.done or not self._started:
            self._check_running()
        index = (action if type(action) is int and 0 <= action < self._n_actions   # the usual case
                 else self.actions.index(action))
        self.turn += 1
        self._step_reward = 0.0
        self._messages = []
        self._act(index)
        return self._finish_step(self._step_reward, False, None)

    def forfeit(self, reason: str | None = None) -> tuple[str, float, bool, bool, dict]:
        """A turn without a valid action: the world is unchanged, the turn counter advances."""
        self._check_running()
        self.turn += 1
        self._messages = ["No valid action: nothing happened."]
        return self._finish_step(0.0, True, reason)

    def render(self) -> str | None:
        if self.render_mode == "ansi":
            return self._frame.render() if self._started else None
        return None

    # -- state ------------------------------------------------------------------------------------------
    done: bool    # the episode has terminated or been truncated (set by finish() and the turn cap)

    @property
    def frame(self) -> Frame:
        if not self._started:
            raise RuntimeError(f"{self.task_id}: call reset(seed=...) first")
        return self._frame

    def system_prompt(self) -> str:
        fields = self.prompt_fields()
        fields.setdefault("max_turns", self.max_turns)
        lines = [f"You are playing {self.title}. " + self.rules.format_map(fields)]
        if self.rewards:
            lines.append("Rewards: " + self.rewards.format_map(fields))
        ends = self.ends.format_map(fields)
        lines.append(f"The episode ends {ends + ', or ' if ends else ''}after {self.max_turns} turns.")
        lines.append(OBSERVATION_CONVENTIONS + (" " + AXES_CONVENTION if self.axes else ""))
        lines.append("Actions:")
        lines.extend(self.actions.prompt_lines())
        lines.append(ACTION_FORMAT)
        return "\n".join(lines)

    # -- internals --------------------------------------------------------------------------------------
    def _make_params(self, params: dict[str, Any]):
        names = [f.name for f in dataclasses.fields(self.Params)]
        unknown = sorted(set(params) - set(names))
        if unknown:
            raise ValueError(f"{self.task_id}: unknown parameter {unknown[0]!r}; "
                             f"valid parameters: {', '.join(names + ['max_turns']) }")
        values = self.Params(**params)
        try:
            check_params(values)
        except ParamError as e:
            raise ParamError(f"{self.task_id}: {e}") from None
        return values

    def _reset_counters(self) -> None:
        self.turn = 0
        self._of_turns = f"/{self.max_turns}"     # (the HUD's "Step t/N" tail)
        self.episode_return = 0.0
        self.won: bool | None = None
        self._terminated = False
        self._truncated = False
        # terminated or truncated: a plain attribute, not a property (games read it often)
        self.done = False
        self._step_reward = 0.0
        self._messages: list[str] = []
        self._clamped = False

    def _check_running(self) -> None:
        if not self._started:
            raise RuntimeError(f"{self.task_id}: call reset(seed=...) before step()")
        if self._terminated or self._truncated:
            how = "terminated" if self._terminated else "truncated"
            raise EpisodeEnded(f"{self.task_id}: the episode already ended ({how} at step "
                               f"{self.turn}/{self.max_turns}); call reset() to start another")

    def _finish_step(self, reward: float, forfeit: bool, reason: str | None):
        if reward:   # (most turns pay nothing: the return, already in bounds, stays)
            if self.tier == "standard":
                total = self.episode_return + reward
                if total > 1.0 + _RETURN_EPS or total < -1.0 - _RETURN_EPS:
                    self._clamped = True
                    reward = min(1.0, max(-1.0, total)) - self.episode_return
            self.episode_return += reward
            if abs(reward) > _RETURN_EPS:       # every paying turn says so, once, for every game
                self._messages.append(f"Reward {reward:+.3g}")
        if self.turn >= self.max_turns and not self._terminated:
            self._truncated = self.done = True
        frame = self._frame = self._build_frame()
        # (``_info``, written out: a step makes one)
        info = {"frame": frame, "turn": self.turn, "return": self.episode_return, "won": self.won,
                "forfeit": forfeit, "clamped": self._clamped}
        if forfeit:
            info["forfeit_reason"] = reason
        # (the base ``_build_frame`` has just rendered its frame; a game's own has not)
        text = self._obs_text if self._plain_frame else render(
            frame, self._legend_text if frame.legend is self._legend else None)
        return text, float(reward), self._terminated, self._truncated, info

    def _build_frame(self) -> Frame:
        hud = self._hud()
        hud = f"Step {self.turn}{self._of_turns} | {hud}" if hud else f"Step {self.turn}{self._of_turns}"
        grid = tuple(self._grid())
        vocab = self.glyphs if self._plain_vocab else self.vocab()
        if vocab is not self._legend_vocab:
            self._legend_vocab, self._legend_memo = vocab, legends_for(vocab_entries(vocab))
            self._legend_bits = -1
        memo = self._legend_memo
        bits = self._glyph_bits(memo) if self._own_bits else None
        if bits is None:
            known = memo.rows
            bits = 0
            try:   # (the glyphs of a row seen before are remembered: most rows repeat)
                for row in grid:
                    bits |= known[row]
            except KeyError:
                bits = memo.grid_bits(grid)
        if bits != self._legend_bits:
            self._legend_bits = bits
            self._legend, self._legend_text = memo.legend(bits)
        messages = self._messages
        message = " ".join(messages) if messages else ""
        if self._plain_frame:   # the observation text too (``render``'s, written out)
            self._obs_text = "\n".join((hud, *grid, self._legend_text, message) if message
                                   else (hud, *grid, self._legend_text))
        return new_frame(grid, self._legend, hud, message, self.axes)

    def _info(self, *, forfeit: bool) -> dict[str, Any]:
        return {"frame": self._frame, "turn": self.turn, "return": self.episode_return,
                "won": self.won, "forfeit": forfeit, "clamped": self._clamped}
