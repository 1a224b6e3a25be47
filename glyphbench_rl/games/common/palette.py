"""The glyphs every family draws the same way, so a wall or the goal looks alike in every task.

A family imports these rather than typing its own; glyphs that only one game needs stay in that
game's module (its legend says what they mean there).
"""

WALL = "█"
FLOOR = "·"
UNSEEN = "░"      # a cell outside the view or not seen yet
GOAL = "◎"
PLAYER = "@"      # the player where facing does not matter (MiniGrid draws ▲▶▼◀)
LAVA = "≈"
