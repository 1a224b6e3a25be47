"""Opponent games: one shared turn loop (your move, then the built-in opponent's) and its outcomes.

A game subclasses :class:`VersusTask` and supplies, besides ``_setup``/``_grid``/``_hud``:

* ``_agent_move(action) -> str | None`` applies your move, or returns a message when the move is
  illegal (a full column, a taken cell): then nothing changes, the turn is wasted and the
  opponent waits;
* ``_opponent_move()`` the opponent's reply, every choice drawn from ``self.rng`` (games where
  both sides move at once, like Tron, apply both moves here; games against a hidden setup, like
  Battleship, have no reply);
* ``_result() -> WIN | LOSS | DRAW | None``, asked after each move.

The first decided result ends the episode with its reward from ``outcome_rewards`` (+1 / -1 / 0
unless a game scales them so that its shaping plus outcome stays in [-1, 1]). Running out of
turns is not an outcome: it ends the episode with nothing more.

The opponent's strength is a parameter: :func:`choose` plays one of the moves its search found
best with probability ``strength`` and a uniformly random legal move otherwise.
"""

from __future__ import annotations

from typing import Callable, ClassVar, Mapping, Sequence, TypeVar

import numpy as np

from ...core import GlyphTask

WIN, LOSS, DRAW = "win", "loss", "draw"
OUTCOME_TEXT = {WIN: "You win.", LOSS: "You lose.", DRAW: "Draw."}
# The rewards sentence every two-player game uses (fields come from VersusTask.prompt_fields).
OUTCOME_REWARDS = "a win gives {win_reward:+g}, a loss {loss_reward:+g}, a draw or running out of turns 0."

T = TypeVar("T")


def choose(rng: np.random.Generator, strength: float,
           best: Sequence[T] | Callable[[], Sequence[T]], legal: Sequence[T]) -> T:
    """The opponent's pick: one of ``best`` (uniformly) with probability ``strength``, else any
    of ``legal`` (which must not be empty; an empty ``best`` means a random legal move).

    ``best`` may be a function, called only when the strong branch is taken, so a costly search
    is skipped on the turns the opponent plays at random. One uniform draw decides both the
    branch and the pick, so every opponent move costs the stream exactly one number.
    """
    u = rng.random()
    if u < strength:
        u /= strength                            # uniform on [0, 1) again, for the pick
        moves = best() if callable(best) else best
        if moves:
            return moves[min(int(u * len(moves)), len(moves) - 1)]
    else:
        u = (u - strength) / (1.0 - strength)
    return legal[min(int(u * len(legal)), len(legal) - 1)]


class VersusTask(GlyphTask):
    outcome_rewards: ClassVar[Mapping[str, float]] = {WIN: 1.0, LOSS: -1.0, DRAW: 0.0}

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"win_reward": self.outcome_rewards[WIN],
                                          "loss_reward": self.outcome_rewards.get(LOSS, 0.0)}

    # -- hooks -----------------------------------------------------------------------------------
    def _agent_move(self, action: int) -> str | None:
        raise NotImplementedError

    def _opponent_move(self) -> None:
        """No reply by default (a game against a hidden setup)."""

    def _result(self) -> str | None:
        raise NotImplementedError

    # -- the turn loop -----------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        problem = self._agent_move(action)
        if problem is not None:
            self.say(problem)
            return
        if not self._settle():
            self._opponent_move()
            self._settle()

    def _settle(self) -> bool:
        result = self._result()
        if result is None:
            return False
        self.conclude(result)
        return True

    def conclude(self, result: str) -> None:
        """End the episode with ``result``'s reward and message (a draw is not a win)."""
        self.reward(self.outcome_rewards[result])
        self.say(OUTCOME_TEXT[result])
        self.finish(won=result == WIN)
