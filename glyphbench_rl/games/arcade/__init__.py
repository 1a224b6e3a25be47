"""Arcade: grid re-imaginings of Atari 2600 games, each registered twice from one parameter set:
``glyphbench/miniatari-<game>-v0`` (MiniAtari, standard tier: a compact field, a return in
[-1, 1]) and ``glyphbench/atari-<game>-v0`` (Atari, extended tier: a larger field, lives, a long
horizon, native-style points).

Engine-level modules, which the games import (and nothing else of the family):
- ``engine``: ``ArcadeTask``, ``ArcadeParams``, the score rules of patterns A/B/C/D (``Tally``,
  ``Milestones``, ``Duel``), lives, the still-rows-plus-movers field, the HUD, and
  ``register_arcade`` (both presets from one call);
- ``bodies``: bodies with a velocity and swept motion, wrapping, guns (range, cooldown,
  limit), formations that sweep and descend, scripted opponents (``track``, ``chase``),
  countdowns (fuel, oxygen, clocks);
- ``chase``: maze chase and collect: lattice mazes, a ``MazeTask`` with compass moves and
  ghosts that chase, scatter, scare, patrol or wander;
- ``hopping``: lane hopping: drifting rows that carry a rider, pyramid hops, floors and ladders.
- ``shooter``: the fixed-bottom shooter family's ``Shooter`` (cannon, lanes, gun, bombs) and
  ``Pack`` of enemies, ``march`` (formations), ``bounce``.
- ``scroller``: scrolling worlds (``Strip``: the window that moves a line a scroll; ``Channel``:
  a river or road of wandering width; ``Pacer``: periodic or speed-driven timing; ``Camera``:
  a view following the player around a wrapping world);
- ``duel``: paddle, ball and sports duels (``Ball`` with reflecting walls, paddle-third
  ``deflect``, ``serve``, the scripted ``pursue``, ``Possession``, tennis-style ``Match``);
- ``pinball``: pinball tables (``PinballTask``: a ball under gravity, flippers that swing it up
  by the part struck, bumpers, drop-target banks, spinners, rollovers, rails, drains, a plunger,
  the nudge and the tilt);
- ``arena``: free-roam shooters (``ArenaTask``: facing fire with a reach, chasers that slide
  around walls, drifting foes, foe shells, wrap-around fields, an air or fuel countdown,
  reinforcements);
- ``climbing``: vertical worlds seen a screen or a window at a time (``Tower``, ``ClimbTask``:
  a mine shaft's screens with a ``RoomMap``, a facade that scrolls), falling objects, a pack
  against gravity, critters that pace or climb;
- ``sectors``: space games flown over a map of places to enter (a ship that keeps its velocity
  under gravity, rotate-and-thrust ``FlightTask``, ``Sectors`` with the HUD's chart);
- ``sidescroll``: side-scrolling stages longer than the screen (``Course``: the stage's rows and
  the view that follows the player, forward or backward; ``Leap``: a jump off the ground line;
  ``fall``; ``ScrollTask``: the task drawn on a course's view);
- ``dungeon``: worlds of rooms seen one at a time on a ``rooms.RoomMap`` (``DungeonTask``, an
  arena: rooms built once and kept, monsters that wander and come down the shortest way when
  near, corpses, sideways-only fire, a zone clock, a flash that clears the room, a hunter for
  lingering);
- ``platform``: side-view platform rooms (``Platformer``: floors, gravity and deadly falls, a
  jump arc, ladders, ropes, swinging vines, hazards; ``Walker`` monsters, ``Blink`` cells);
- ``rooms``: ``RoomMap``, the HUD's map of a many-room world's rooms, visited or not.
"""

from . import alien  # noqa: F401
from . import amidar  # noqa: F401
from . import assault  # noqa: F401
from . import asterix  # noqa: F401
from . import asteroids  # noqa: F401
from . import atlantis  # noqa: F401
from . import bankheist  # noqa: F401
from . import battlezone  # noqa: F401
from . import beamrider  # noqa: F401
from . import berzerk  # noqa: F401
from . import bowling  # noqa: F401
from . import boxing  # noqa: F401
from . import breakout  # noqa: F401
from . import centipede  # noqa: F401
from . import choppercommand  # noqa: F401
from . import crazyclimber  # noqa: F401
from . import defender  # noqa: F401
from . import demonattack  # noqa: F401
from . import doubledunk  # noqa: F401
from . import enduro  # noqa: F401
from . import fishingderby  # noqa: F401
from . import freeway  # noqa: F401
from . import frostbite  # noqa: F401
from . import gopher  # noqa: F401
from . import gravitar  # noqa: F401
from . import hero  # noqa: F401
from . import icehockey  # noqa: F401
from . import jamesbond  # noqa: F401
from . import kangaroo  # noqa: F401
from . import krull  # noqa: F401
from . import kungfumaster  # noqa: F401
from . import montezumarevenge  # noqa: F401
from . import mspacman  # noqa: F401
from . import namethisgame  # noqa: F401
from . import phoenix  # noqa: F401
from . import pitfall  # noqa: F401
from . import pong  # noqa: F401
from . import privateeye  # noqa: F401
from . import qbert  # noqa: F401
from . import riverraid  # noqa: F401
from . import roadrunner  # noqa: F401
from . import robotank  # noqa: F401
from . import seaquest  # noqa: F401
from . import skiing  # noqa: F401
from . import solaris  # noqa: F401
from . import spaceinvaders  # noqa: F401
from . import stargunner  # noqa: F401
from . import surround  # noqa: F401
from . import tennis  # noqa: F401
from . import timepilot  # noqa: F401
from . import tutankham  # noqa: F401
from . import upndown  # noqa: F401
from . import venture  # noqa: F401
from . import videopinball  # noqa: F401
from . import wizardofwor  # noqa: F401
from . import yarsrevenge  # noqa: F401
from . import zaxxon  # noqa: F401
