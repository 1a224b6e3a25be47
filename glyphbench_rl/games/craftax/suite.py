"""The 60 Craftax tasks, one ``Scenario`` each (see ``scenarios`` for the vocabulary).

Horizons, kits and reward shares follow the other implementation's definitions (specs section
1.2) wherever Craftax's own rules allow; where a definition relied on a rule Craftax does not
have, the nearest Craftax mechanic stands in (the README lists each case): floors' ladder gates of
k kills start the floor's kill count at 8 - k; bosses invented there become Craftax's own mobs
(the necromancer on the graveyard; a troll on the troll mines); "dark" floors are Craftax's dark
floors; maximum health is Craftax's 8 + strength.
"""

from __future__ import annotations

from .scenarios import (Clear, Event, Gate, GateAt, MoveLadder, Mobs, NearLadder, NoMobs, Potions, Remove,
                        Scatter, Stamp, Term, scenario)
from .state import Settings
from .tables import BlockType as B

DRILL = Settings(intrinsics=False, daylight=False, spawning=False)     # the small-arena drills
ARENA = Settings(spawning=False)                                       # fights: only the task's mobs
CALM = Settings(intrinsics=False, daylight=False, spawning=False)
NIGHT = 160                  # a timestep early in the night (the light is below half from 148 to 272)
DUSK = 143                   # night falls five turns later
SPELLS = (True, True)
ALL_POTIONS = (1, 1, 1, 1, 1, 1)
ARMOUR_IRON, ARMOUR_DIAMOND = (1, 1, 1, 1), (2, 2, 2, 2)


def kills(name: str, n: int, share: float, says: str) -> Term:
    return Term(f"kill-{name}", f"kills.{name}", share / n, f"each {says} killed", cap=n)


def stage(name: str, test: str, share: float, says: str) -> Term:
    return Term(name, test, share, says)


def pockets(*spec) -> tuple:
    """Stamps of resource pockets: (block, row offset, col offset, rows, cols) rectangles."""
    out = []
    for block, r, c, h, w in spec:
        out.append(Stamp(block, tuple((r + i, c + j) for i in range(h) for j in range(w))))
    return tuple(out)


CLUSTER = pockets((B.TREE, -5, -5, 2, 3), (B.STONE, -5, 3, 2, 3), (B.COAL, 4, -5, 1, 2), (B.IRON, 4, 3, 1, 3))
CRAFTER_22 = ("collect_wood", "place_table", "eat_cow", "collect_sapling", "collect_drink",
              "make_wood_pickaxe", "make_wood_sword", "place_plant", "defeat_zombie", "collect_stone",
              "place_stone", "eat_plant", "defeat_skeleton", "make_stone_pickaxe", "make_stone_sword",
              "wake_up", "place_furnace", "collect_coal", "collect_iron", "collect_diamond",
              "make_iron_pickaxe", "make_iron_sword")

# -- A. small-arena drills -------------------------------------------------------------------------
scenario(name="choptrees", horizon=120, world="blank", settings=DRILL,
         objective="Collect 10 wood by chopping trees (DO facing a tree).",
         edits=(Scatter(B.TREE, 28, 2, 8),),
         terms=(Term("wood", "got.wood", 0.1, "each wood collected", cap=10),),
         success="got.wood >= 10", progress_keys=("got.wood",), death=0.0)
scenario(name="minestone", horizon=120, world="blank", settings=DRILL, kit=dict(pickaxe=1),
         objective="Mine 10 stone with your wood pickaxe.",
         edits=(Scatter(B.STONE, 24, 5, 9), Scatter(B.TREE, 6, 2, 9)),
         terms=(Term("stone", "got.stone", 0.1, "each stone mined", cap=10),),
         success="got.stone >= 10", progress_keys=("got.stone",), death=0.0)
scenario(name="gatherresources", horizon=160, world="blank", settings=DRILL,
         objective="Hold at least 5 wood and 5 stone at once (stone needs a wood pickaxe, made at a table).",
         edits=(Scatter(B.TREE, 14, 2, 8), Scatter(B.STONE, 12, 3, 9)),
         terms=(Term("wood", "got.wood", 0.1, "each wood collected", cap=5),
                Term("stone", "got.stone", 0.1, "each stone collected", cap=5)),
         success="holds.wood >= 5 and holds.stone >= 5", progress_keys=("holds.wood", "holds.stone"), death=0.0)
scenario(name="craftpickaxe", horizon=140, world="blank", settings=DRILL,
         objective="Make a wood pickaxe: collect wood, place a crafting table, craft the pickaxe next to it.",
         edits=(Scatter(B.TREE, 14, 2, 6),),
         terms=(stage("pickaxe", "done.make_wood_pickaxe >= 1", 1.0, "for making a wood pickaxe"),),
         success="done.make_wood_pickaxe >= 1", death=0.0)
scenario(name="craftsword", horizon=200, world="blank", settings=DRILL,
         objective="Make a stone sword (wood, a table, a wood pickaxe to mine stone, then the sword).",
         edits=pockets((B.TREE, -2, -7, 4, 4)) + pockets((B.STONE, -2, 4, 3, 3)),
         terms=(stage("sword", "done.make_stone_sword >= 1", 1.0, "for making a stone sword"),),
         success="done.make_stone_sword >= 1", death=0.0)
scenario(name="craftchain", horizon=260, world="blank", settings=DRILL,
         objective="Work up to an iron sword: table, wood pickaxe, furnace, stone pickaxe, iron and coal, iron sword.",
         edits=CLUSTER + (Scatter(B.TREE, 6, 4, 9), Scatter(B.STONE, 6, 4, 9)),
         terms=(stage("table", "done.place_table >= 1", 1 / 6, "for placing a table"),
                stage("wpick", "done.make_wood_pickaxe >= 1", 1 / 6, "for a wood pickaxe"),
                stage("furnace", "done.place_furnace >= 1", 1 / 6, "for placing a furnace"),
                stage("spick", "done.make_stone_pickaxe >= 1", 1 / 6, "for a stone pickaxe"),
                stage("ore", "holds.iron >= 1 and holds.coal >= 1", 1 / 6, "for holding iron and coal together"),
                stage("isword", "done.make_iron_sword >= 1", 1 / 6, "for an iron sword")),
         success="done.make_iron_sword >= 1", death=0.0)
scenario(name="fightzombie", horizon=50, world="blank", settings=Settings(daylight=False, spawning=False),
         kit=dict(sword=1), topics=("fight",),
         objective="Kill the 2 zombies with your wood sword.",
         edits=(Mobs("zombie", 2, 3, 4), Stamp(B.TREE, ((2, 2),))),
         terms=(kills("zombie", 2, 1.0, "zombie"),), success="kills.zombie >= 2",
         progress_keys=("kills.zombie",))
scenario(name="survivehorde", horizon=160, settings=ARENA, time=NIGHT, kit=dict(sword=2, stone=6),
         topics=("fight",), objective="Kill 8 monsters at night; more arrive at turns 25, 50 and 75.",
         edits=(Clear(3), Mobs("zombie", 3, 3, 3), Mobs("skeleton", 2, 3, 3)),
         events=(Event("turn >= 25", (Mobs("zombie", 1, 5, 7),)), Event("turn >= 50", (Mobs("skeleton", 1, 5, 7),)),
                 Event("turn >= 75", (Mobs("zombie", 1, 5, 7),))),
         terms=(kills("monsters", 8, 1.0, "monster"),), success="kills.monsters >= 8",
         progress_keys=("kills.monsters",))
scenario(name="dungeonexplore", horizon=180, floor=1, kit=dict(sword=2, armour=ARMOUR_IRON, potions=ALL_POTIONS),
         topics=("fight", "floors"),
         objective="Explore the dungeon: kill 3 monsters to open the ladder down, then DESCEND on it.",
         edits=(Gate(3), NoMobs(), Mobs("orc soldier", 2, 4, 10), Mobs("orc mage", 1, 4, 10)),
         terms=(kills("monsters", 3, 0.6, "monster"), stage("descend", "level >= 2", 0.4, "for descending")),
         success="level >= 2")
scenario(name="dungeonclear", horizon=220, floor=1, settings=ARENA, kit=dict(sword=3, armour=ARMOUR_IRON, potions=ALL_POTIONS),
         topics=("fight",),
         objective="Kill the 5 monsters of this dungeon floor (3 orc soldiers, 2 orc mages).",
         edits=(NoMobs(), Mobs("orc soldier", 3, 3, 14), Mobs("orc mage", 2, 4, 14)),
         terms=(kills("monsters", 5, 1.0, "monster"),), success="kills.monsters >= 5",
         progress_keys=("kills.monsters",))

# -- B. surface scenarios --------------------------------------------------------------------------
scenario(name="survive-hunger", horizon=120, kit=dict(sword=1), player=dict(player_food=0, player_health=5),
         objective="You are starving: eat (kill a cow, or eat a ripe plant) and stay alive until turn 120.",
         edits=(Remove(B.RIPE_PLANT, 5, B.PLANT),),
         terms=(stage("eat", "ate >= 1", 0.5, "the first time you eat"),
                stage("alive", "turn >= 120 and ate >= 1", 0.5, "for being alive and fed at turn 120")),
         success="turn >= 120")
scenario(name="survive-thirst", horizon=120, player=dict(player_drink=0, player_health=5),
         objective="You are parched: find water, drink (DO facing water) and stay alive until turn 120.",
         edits=(Remove(B.WATER, 6, B.GRASS), Stamp(B.WATER, ((0, 10), (1, 10)))),
         terms=(stage("drink", "drank >= 1", 0.5, "the first time you drink"),
                stage("alive", "turn >= 120 and drank >= 1", 0.5, "for being alive at turn 120 after drinking")),
         success="turn >= 120")
scenario(name="survive-night", horizon=150, time=198, kit=dict(sword=2, stone=4), player=dict(player_health=8),
         topics=("fight",), objective="Night is falling: stay alive until day breaks (about turn 75).",
         events=(Event("turn >= 25", (Mobs("zombie", 1, 4, 6),)), Event("turn >= 50", (Mobs("skeleton", 1, 4, 6),))),
         terms=(stage("dawn", "turn >= 75", 1.0, "when day breaks and you are alive"),),
         success="turn >= 75")
scenario(name="survive-wild", horizon=200, time=118, player=dict(player_food=2, player_drink=2, player_health=6),
         objective="You start hungry, thirsty and hurt: survive 200 turns in the wild, keeping fed, watered and rested; night falls at turn 30.",
         terms=(Term("alive", "turn", 0.1, "each 20 turns alive", cap=10, per=20),), success="")
scenario(name="fight-cow", horizon=80, settings=ARENA, kit=dict(sword=1), topics=("fight",),
         objective="Hunt the cow; at turn 30 a zombie comes for you.",
         edits=(NoMobs(), Mobs("cow", 1, 7, 9)),
         events=(Event("turn >= 30", (Mobs("zombie", 1, 4, 8),), "A zombie approaches."),),
         terms=(stage("cow", "kills.cow >= 1", 0.7, "for killing the cow"),
                stage("zombie", "kills.zombie >= 1", 0.3, "for killing the zombie")),
         success="kills.cow >= 1")
scenario(name="fight-zombies", horizon=130, settings=CALM, kit=dict(sword=2, armour=ARMOUR_IRON),
         topics=("fight",),
         objective="Kill 5 zombies (at most 3 are out at once).", edits=(Clear(4), Mobs("zombie", 5, 2, 5)),
         terms=(kills("zombie", 5, 1.0, "zombie"),), success="kills.zombie >= 5", progress_keys=("kills.zombie",))
scenario(name="fight-skeletons", horizon=150, settings=Settings(intrinsics=False, spawning=False),
         kit=dict(sword=1), topics=("fight",), objective="Kill 4 skeletons; they shoot arrows.",
         edits=(Clear(6), Mobs("skeleton", 4, 3, 6)),
         terms=(kills("skeleton", 4, 1.0, "skeleton"),), success="kills.skeleton >= 4", progress_keys=("kills.skeleton",))
scenario(name="craft-ironset", horizon=480, edits=(NoMobs(), Clear(7)) + CLUSTER + pockets((B.COAL, 5, -5, 1, 2), (B.IRON, 5, 3, 1, 1)),
         objective="Make an iron pickaxe and an iron sword (a table and a furnace must be near).",
         terms=(stage("ipick", "done.make_iron_pickaxe >= 1", 0.5, "for an iron pickaxe"),
                stage("isword", "done.make_iron_sword >= 1", 0.5, "for an iron sword")),
         success="done.make_iron_pickaxe >= 1 and done.make_iron_sword >= 1")
scenario(name="mine-iron", horizon=140, kit=dict(pickaxe=2),
         objective="Mine 5 iron with your stone pickaxe.",
         edits=(NoMobs(), Clear(4), Remove(B.IRON, 9, B.STONE), Scatter(B.IRON, 8, 9, 13),
                Scatter(B.STONE, 8, 3, 9)),
         terms=(Term("iron", "got.iron", 0.2, "each iron mined", cap=5),), success="holds.iron >= 5",
         progress_keys=("holds.iron",))
scenario(name="build-shelter", horizon=150, kit=dict(pickaxe=1), settings=ARENA,
         objective="Mine stone and place 6 stone blocks (PLACE_STONE) while zombies roam.",
         edits=(Clear(2), Scatter(B.STONE, 12, 2, 7), Scatter(B.TREE, 6, 3, 7), Mobs("zombie", 3, 5, 7)),
         terms=(Term("blocks", "placed.stone", 1 / 6, "each stone block placed", cap=6),),
         success="placed.stone >= 6", progress_keys=("placed.stone",))
scenario(name="plant-farm", horizon=200, kit=dict(sapling=6, sword=1), player=dict(player_food=5), settings=ARENA,
         objective="Plant your 6 saplings on grass (PLACE_PLANT) and eat a ripe plant (DO facing it).",
         edits=(Clear(3), Stamp(B.RIPE_PLANT, ((-4, 3), (4, -3))), Mobs("zombie", 2, 6, 7)),
         terms=(Term("plant", "placed.plant", 0.1, "each sapling planted", cap=6),
                stage("eat", "done.eat_plant >= 1", 0.4, "for eating a ripe plant")),
         success="placed.plant >= 6 and done.eat_plant >= 1", progress_keys=("placed.plant",))
scenario(name="find-water", horizon=180, player=dict(player_drink=0, player_health=6), settings=ARENA,
         objective="There is no water nearby and you are parched: find water and drink.",
         edits=(Remove(B.WATER, 12, B.SAND), Mobs("zombie", 1, 6, 8)),
         terms=(stage("drink", "drank >= 1", 1.0, "for drinking"),), success="drank >= 1")
scenario(name="find-diamond", horizon=220, kit=dict(pickaxe=3), player=dict(player_food=6, player_drink=6),
         objective="Find and mine a diamond with your iron pickaxe.",
         edits=(Scatter(B.DIAMOND, 2, 12, 20, on=B.STONE), Scatter(B.DIAMOND, 1, 16, 22), Mobs("zombie", 1, 8, 10)),
         terms=(stage("diamond", "got.diamond >= 1", 1.0, "for mining a diamond"),), success="got.diamond >= 1")
scenario(name="firstday", horizon=220,
         objective="Unlock as many of Crafter's 22 achievements as you can on your first day.",
         terms=tuple(stage(a, f"done.{a} >= 1", 1 / 22, f"for {a.replace('_', ' ')}") for a in CRAFTER_22),
         success="", topics=("craft", "fight"))
scenario(name="iron-bootstrap", horizon=320, edits=(NoMobs(), Clear(7)) + CLUSTER,
         objective="Get iron: wood, stone, a wood and a stone pickaxe, a table and a furnace, then mine iron.",
         terms=(stage("wood", "got.wood >= 1", 1 / 7, "for wood"), stage("stone", "got.stone >= 1", 1 / 7, "for stone"),
                stage("wpick", "done.make_wood_pickaxe >= 1", 1 / 7, "for a wood pickaxe"),
                stage("spick", "done.make_stone_pickaxe >= 1", 1 / 7, "for a stone pickaxe"),
                stage("table", "done.place_table >= 1", 1 / 7, "for a table"),
                stage("furnace", "done.place_furnace >= 1", 1 / 7, "for a furnace"),
                stage("iron", "got.iron >= 1", 1 / 7, "for iron")),
         success="holds.iron >= 1 and done.place_furnace >= 1")
scenario(name="diamond-bootstrap", horizon=420,
         edits=(NoMobs(), Clear(7)) + CLUSTER + (Stamp(B.DIAMOND, ((-3, -3), (-3, -2))),),
         objective="Get a diamond: the whole chain up to an iron pickaxe, then mine a diamond.",
         terms=(stage("wood", "got.wood >= 1", 1 / 9, "for wood"), stage("stone", "got.stone >= 1", 1 / 9, "for stone"),
                stage("wpick", "done.make_wood_pickaxe >= 1", 1 / 9, "for a wood pickaxe"),
                stage("spick", "done.make_stone_pickaxe >= 1", 1 / 9, "for a stone pickaxe"),
                stage("table", "done.place_table >= 1", 1 / 9, "for a table"),
                stage("furnace", "done.place_furnace >= 1", 1 / 9, "for a furnace"),
                stage("iron", "got.iron >= 1", 1 / 9, "for iron"),
                stage("ipick", "done.make_iron_pickaxe >= 1", 1 / 9, "for an iron pickaxe"),
                stage("diamond", "got.diamond >= 1", 1 / 9, "for a diamond")),
         success="got.diamond >= 1")
scenario(name="wave-defense", horizon=180, settings=CALM, kit=dict(sword=2, stone=6), topics=("fight",),
         objective="Hold out against zombie waves at turns 1, 60 and 120 (3, 3 and 4 zombies).",
         edits=(Clear(3), Scatter(B.STONE, 5, 3, 6), Scatter(B.TREE, 5, 3, 6)),
         events=(Event("turn >= 1", (Mobs("zombie", 3, 6, 9),)), Event("turn >= 60", (Mobs("zombie", 3, 6, 9),)),
                 Event("turn >= 120", (Mobs("zombie", 4, 6, 9),))),
         terms=(kills("zombie", 10, 1.0, "zombie"),), success="", death=0.0, progress_keys=("kills.zombie",))

# -- C. floors and fights --------------------------------------------------------------------------
FLOOR_TOPICS = ("fight", "floors")
scenario(name="dungeon", horizon=480, floor=1, kit=dict(sword=2, pickaxe=2, wood=3, coal=3, armour=ARMOUR_IRON), topics=FLOOR_TOPICS,
         objective="Find the ladder down on the dungeon floor; it opens after 3 kills; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 2", 1.0, "for reaching floor 2"),),
         success="level >= 2")
_FLOOR_KIT = dict(sword=3, wood=5, coal=5, armour=ARMOUR_IRON)
scenario(name="gnomish-mines", horizon=480, floor=2, kit=_FLOOR_KIT, topics=FLOOR_TOPICS + ("torch",),
         objective="Cross the dark gnomish mines: 3 kills open the ladder down; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 3", 1.0, "for reaching floor 3"),),
         success="level >= 3")
_MAGIC = dict(learned_spells=SPELLS, player_mana=9)
scenario(name="sewers", horizon=480, floor=3, kit=_FLOOR_KIT | dict(potions=ALL_POTIONS), player=_MAGIC,
         topics=FLOOR_TOPICS + ("magic",), objective="Cross the sewers: 3 kills open the ladder down; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 4", 1.0, "for reaching floor 4"),),
         success="level >= 4")
scenario(name="vaults", horizon=480, floor=4, kit=_FLOOR_KIT | dict(sword=4, ruby=1, potions=ALL_POTIONS),
         player=_MAGIC, topics=FLOOR_TOPICS + ("magic",),
         objective="Cross the vaults: 3 kills open the ladder down; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 5", 1.0, "for reaching floor 5"),),
         success="level >= 5")
_DEEP_KIT = dict(sword=4, bow=1, arrows=10, wood=5, coal=5, armour=ARMOUR_DIAMOND, potions=ALL_POTIONS)
scenario(name="troll-mines", horizon=480, floor=5, kit=_DEEP_KIT, player=_MAGIC, topics=FLOOR_TOPICS + ("magic",),
         objective="Cross the dark troll mines: 3 kills open the ladder down; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 6", 1.0, "for reaching floor 6"),),
         success="level >= 6")
scenario(name="fire-realm", horizon=480, floor=6, kit=_DEEP_KIT,
         player=_MAGIC | dict(sword_enchantment=2, armour_enchantments=(1, 1, 1, 1)), topics=FLOOR_TOPICS + ("magic",),
         objective="Cross the fire realm (your sword is ice-enchanted, your armour fire-enchanted): 3 kills open the ladder; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 7", 1.0, "for reaching floor 7"),),
         success="level >= 7")
scenario(name="ice-realm", horizon=480, floor=7, kit=_DEEP_KIT,
         player=_MAGIC | dict(sword_enchantment=1, armour_enchantments=(2, 2, 2, 2)), topics=FLOOR_TOPICS + ("magic",),
         objective="Cross the dark ice realm (fire-enchanted sword, ice-enchanted armour): 3 kills open the ladder; DESCEND.",
         edits=(Gate(3),), terms=(stage("down", "level >= 8", 1.0, "for reaching the graveyard"),),
         success="level >= 8")
# The necromancer (Craftax's own boss): 8 hits while he is vulnerable, each raising a 7-turn wave
# of the next floor's monsters, damage x1.5. Upstream's fight as is; the player comes as a late
# game Craftax character would: attributes raised by the XP of the floors (strength 4,
# intelligence 4, dexterity 3), potions saved from the chests, gems for re-enchanting, fire and ice
# enchantment tables beside the start, 3 cells north of him (he stands at the graveyard's centre,
# (24, 24)), to turn the sword to ice for the fire realm's wave and the armour to ice for the ice
# realm's. He is vulnerable at the start (no wave before the first hit).
scenario(name="necromancer", horizon=512, floor=8,
         kit=dict(sword=4, bow=1, arrows=20, wood=10, coal=10, ruby=2, sapphire=6, armour=ARMOUR_DIAMOND,
                  potions=(12,) * 6),
         player=_MAGIC | dict(sword_enchantment=1, bow_enchantment=1, armour_enchantments=(1, 1, 1, 1),
                              player_strength=4, player_health=12, player_intelligence=4, player_mana=18,
                              player_dexterity=3, player_position=(21, 24),
                              boss_timesteps_to_spawn_this_round=0),
         edits=(Stamp(B.PATH, ((0, 0),)), Stamp(B.ENCHANTMENT_TABLE_FIRE, ((0, -2),)),
                Stamp(B.ENCHANTMENT_TABLE_ICE, ((0, 2),))),
         topics=("fight", "boss", "magic"),
         objective="Defeat the necromancer, 3 steps south: hit him (DO) 8 times. Each hit raises a 7-turn wave "
                   "of monsters (floor 1's, then 2's ... 7's) that must all die before he can be hit again. "
                   "The fire realm's wave resists fire, the ice realm's ice: the enchantment tables 2 steps west "
                   "(fire: a ruby) and east (ice: a sapphire) of you re-enchant your sword or armour (9 mana).",
         terms=(Term("hits", "boss", 1 / 8, "each hit on the necromancer", cap=8),), success="boss >= 8",
         progress_keys=("boss",))
scenario(name="bossfight", horizon=480, floor=5, settings=ARENA,
         kit=dict(sword=4, armour=ARMOUR_DIAMOND, wood=3, coal=3, potions=ALL_POTIONS),
         player=_MAGIC | dict(sword_enchantment=1), topics=("fight", "magic"),
         objective="Kill the troll of the troll mines (20 health, hits hard).",
         edits=(NoMobs(), Clear(4), Mobs("troll", 1, 4, 6)),
         terms=(stage("troll", "kills.troll >= 1", 1.0, "for killing the troll"),), success="kills.troll >= 1")
scenario(name="learn-spell", horizon=120, floor=3, kit=dict(sword=3, armour=ARMOUR_IRON), player=dict(player_mana=9),
         topics=("fight", "magic"),
         objective="Open a chest (the floor's first chest holds a book), READ_BOOK to learn a spell, then cast it.",
         edits=(Remove(B.CHEST, 9, B.PATH), Scatter(B.CHEST, 1, 10, 20)),
         terms=(stage("chest", "got.books >= 1", 1 / 3, "for finding the book"),
                stage("learn", "spells >= 1", 1 / 3, "for learning a spell"),
                stage("cast", "cast >= 1", 1 / 3, "for casting it")), success="cast >= 1")
scenario(name="enchant-weapon", horizon=140, floor=4, settings=ARENA, kit=dict(sword=4, ruby=1, armour=ARMOUR_IRON),
         player=dict(player_mana=9), topics=("fight", "magic"),
         objective="Enchant your sword at the fire enchantment table ahead (a ruby and 9 mana), then kill the 2 kobolds.",
         edits=(NoMobs(), Clear(4), Stamp(B.ENCHANTMENT_TABLE_FIRE, ((-2, 0),)), Mobs("kobold", 2, 3, 4)),
         terms=(stage("enchant", "enchant.sword >= 1", 0.5, "for enchanting the sword"),
                kills("kobold", 2, 0.5, "kobold")),
         success="enchant.sword >= 1 and kills.kobold >= 2")
scenario(name="bow-kite", horizon=120, settings=ARENA, kit=dict(bow=1, arrows=6, sword=1, wood=4, stone=4),
         topics=("fight", "craft"), objective="Kill 4 skeletons; arrows (SHOOT_ARROW) are your best weapon; MAKE_ARROW at the table.",
         edits=(Clear(6), Scatter(B.TREE, 5, 7, 9), Stamp(B.CRAFTING_TABLE, ((0, 2),)), Mobs("skeleton", 4, 4, 6)),
         terms=(kills("skeleton", 4, 1.0, "skeleton"),), success="kills.skeleton >= 4")
scenario(name="potion-triage", horizon=120, settings=ARENA, kit=dict(sword=1),
         player=dict(player_health=2, player_mana=0, player_energy=2), topics=("fight", "potions"),
         objective="You are badly hurt. One of your three potions heals: find it, then kill both zombies.",
         edits=(Potions((0, 1, 5)), Clear(3), Mobs("zombie", 2, 5, 6)),
         terms=(stage("heal", "potion.heal >= 1", 0.5, "for drinking the healing potion"), kills("zombie", 2, 0.5, "zombie")),
         success="kills.zombie >= 2")
scenario(name="fight-archers", horizon=160, settings=ARENA, kit=dict(sword=2, bow=1, arrows=4, wood=3, stone=3),
         topics=("fight", "craft"), objective="Kill 5 skeletons (at most 2 are out at once).",
         edits=(Clear(8), Stamp(B.CRAFTING_TABLE, ((0, 2),)), Mobs("skeleton", 5, 4, 7)),
         terms=(kills("skeleton", 5, 1.0, "skeleton"),), success="kills.skeleton >= 5")
scenario(name="fight-spiders", horizon=120, settings=ARENA, kit=dict(sword=3), topics=("fight",),
         objective="Kill 3 kobolds; they throw daggers (the task's old name says spiders).",
         edits=(Clear(6), Mobs("kobold", 3, 3, 6)),
         terms=(kills("kobold", 3, 1.0, "kobold"),), success="kills.kobold >= 3")
scenario(name="fight-bats", horizon=130, settings=ARENA, kit=dict(sword=2), topics=("fight",),
         objective="Kill 6 bats (skeletons are around too; they earn nothing).",
         edits=(Clear(5), Mobs("bat", 6, 1, 3), Mobs("skeleton", 2, 4, 6)),
         terms=(kills("bat", 6, 1.0, "bat"),), success="kills.bat >= 6")
scenario(name="reach-dungeon", horizon=180, kit=dict(sword=2), topics=("fight", "floors"),
         objective="Reach the dungeon: walk to the ladder down on the surface and DESCEND.",
         edits=(NearLadder(6, 11),), terms=(stage("down", "level >= 1", 1.0, "for entering the dungeon"),),
         success="level >= 1")
scenario(name="speedrun", horizon=500, kit=dict(sword=4, bow=1, arrows=20, wood=10, coal=10, armour=ARMOUR_DIAMOND,
                                                 potions=ALL_POTIONS),
         player=_MAGIC | dict(sword_enchantment=1), topics=FLOOR_TOPICS + ("magic",),
         objective="Go as deep as you can: floor 5 wins. Each floor's ladder opens after 2 kills there.",
         edits=(NearLadder(2, 4), GateAt((1, 2, 3, 4), 2)),
         terms=(Term("deeper", "deepest", 0.2, "each new deepest floor", cap=5),), success="deepest >= 5",
         progress_keys=("deepest",))

# -- D. harder combinations ------------------------------------------------------------------------
scenario(name="torchdescend", horizon=300, floor=2,
         kit=dict(sword=3, pickaxe=2, wood=3, coal=3, armour=ARMOUR_IRON, potions=ALL_POTIONS),
         topics=FLOOR_TOPICS + ("torch", "craft"),
         objective="In the dark mines: make torches, light the way, kill 8 monsters to open the ladder, DESCEND.",
         edits=(Clear(3), Stamp(B.CRAFTING_TABLE, ((0, 1),)), Stamp(B.FURNACE, ((1, 0),))),
         terms=(stage("torch", "done.make_torch >= 1", 0.2, "for making torches"),
                stage("light", "placed.torch >= 1", 0.2, "for placing a torch"),
                stage("k4", "kills.monsters >= 4", 0.2, "at 4 kills"), stage("k8", "kills.monsters >= 8", 0.2, "at 8 kills"),
                stage("down", "level >= 3", 0.2, "for descending")), success="level >= 3")
scenario(name="survivenight", horizon=150, time=DUSK, kit=dict(sword=2, stone=6, torches=2), topics=("fight", "torch"),
         objective="Night falls in 5 turns: survive it. Monsters come more often in the dark.",
         edits=(Clear(6), Scatter(B.TREE, 8, 4, 8), Scatter(B.STONE, 6, 4, 8), Mobs("zombie", 2, 6, 8)),
         terms=(stage("n25", "night >= 25", 0.25, "after 25 night turns"), stage("n50", "night >= 50", 0.25, "after 50"),
                stage("n75", "night >= 75", 0.25, "after 75"), stage("dawn", "turn >= 130", 0.25, "at dawn")),
         success="turn >= 130", progress_keys=("night",))
scenario(name="kiteskeletons", horizon=150, settings=ARENA, kit=dict(sword=1), topics=("fight",),
         objective="Kill 4 skeletons with only a wood sword: close in between their shots.",
         edits=(Clear(7), Scatter(B.TREE, 10, 3, 8), Scatter(B.STONE, 8, 3, 8), Mobs("skeleton", 4, 4, 8)),
         terms=(stage("k1", "kills.skeleton >= 1", 0.25, "for the first kill"),
                stage("k2", "kills.skeleton >= 2", 0.25, "for the second"),
                stage("k4", "kills.skeleton >= 4", 0.5, "for the fourth")), success="kills.skeleton >= 4")
scenario(name="dark-ambush", horizon=200, floor=2, settings=ARENA,
         kit=dict(sword=3, bow=1, arrows=10, torches=4, armour=ARMOUR_IRON), topics=("fight", "torch"),
         objective="Kobolds lurk in the dark mines: light torches and kill 4 kobolds.",
         edits=(NoMobs(), Clear(3), Mobs("kobold", 4, 4, 9)),
         terms=(stage("light", "placed.torch >= 1", 0.25, "for the first torch placed"),
                stage("k2", "kills.kobold >= 2", 0.25, "at 2 kills"), stage("k4", "kills.kobold >= 4", 0.5, "at 4 kills")),
         success="kills.kobold >= 4")
scenario(name="floor-clear-9hp", horizon=400, floor=1, kit=dict(sword=3, pickaxe=2, potions=ALL_POTIONS, armour=ARMOUR_IRON),
         topics=FLOOR_TOPICS + ("potions",),
         objective="Clear the dungeon floor the Craftax way: 8 kills open the ladder; DESCEND.",
         terms=(stage("k4", "kills.monsters >= 4", 0.25, "at 4 kills"), stage("k8", "kills.monsters >= 8", 0.5, "at 8 kills"),
                stage("down", "level >= 2", 0.25, "for descending")), success="level >= 2")
scenario(name="spell-only-kill", horizon=200, floor=6, settings=ARENA, kit=dict(sword=1, armour=ARMOUR_IRON),
         player=dict(learned_spells=(False, True), player_intelligence=5, player_mana=21,
                     armour_enchantments=(1, 1, 1, 1)), topics=("fight", "magic"),
         objective="Kill the 2 fire elementals; your wood sword barely scratches them, your iceball does not.",
         edits=(NoMobs(), Clear(5), Mobs("fire elemental", 2, 4, 6)),
         terms=(kills("fire elemental", 2, 1.0, "fire elemental"),), success="kills.monsters >= 2")
scenario(name="descent-gauntlet", horizon=500, floor=1,
         kit=dict(sword=4, bow=1, arrows=12, torches=5, wood=4, coal=4, armour=ARMOUR_IRON, potions=ALL_POTIONS),
         player=_MAGIC, topics=FLOOR_TOPICS + ("torch", "magic"),
         objective="Go down two floors; each ladder opens after 4 kills on its floor.",
         edits=(GateAt((1, 2), 4),),
         terms=(stage("k4", "kills.monsters >= 4", 0.25, "at 4 kills"), stage("d2", "deepest >= 2", 0.25, "for floor 2"),
                stage("k8", "kills.monsters >= 8", 0.25, "at 8 kills"), stage("d3", "deepest >= 3", 0.25, "for floor 3")),
         success="deepest >= 3")
scenario(name="potion-id-stakes", horizon=80, settings=ARENA, kit=dict(sword=1),
         player=dict(player_health=2, player_mana=0, player_energy=4), topics=("fight", "potions"),
         objective="Kill the zombie. You are nearly dead; one of your 3 potions heals, one harms.",
         edits=(Potions((0, 1, 3)), Clear(5), Scatter(B.TREE, 8, 4, 7), Mobs("zombie", 1, 4, 5)),
         terms=(stage("heal", "potion.heal >= 1", 0.5, "for drinking the healing potion"),
                stage("kill", "kills.zombie >= 1", 0.5, "for killing the zombie")), success="kills.zombie >= 1")
scenario(name="clear-floor-8gate", horizon=300, floor=4,
         kit=dict(sword=4, bow=1, arrows=12, armour=ARMOUR_DIAMOND, potions=ALL_POTIONS), player=_MAGIC,
         topics=FLOOR_TOPICS + ("magic",), objective="Clear the vaults: 8 kills open the ladder; DESCEND.",
         terms=(stage("k4", "kills.monsters >= 4", 0.25, "at 4 kills"), stage("k8", "kills.monsters >= 8", 0.5, "at 8 kills"),
                stage("down", "level >= 5", 0.25, "for descending")), success="level >= 5")
RESOURCES = pockets((B.TREE, -6, -6, 1, 5), (B.STONE, -6, 2, 1, 5), (B.COAL, 6, -6, 1, 5), (B.IRON, 6, 2, 1, 5))
scenario(name="surface-to-iron-descend", horizon=500, settings=ARENA, topics=("craft", "fight", "floors"),
         objective="Make an iron pickaxe and an iron sword, kill 3 monsters to open the ladder, and DESCEND.",
         edits=(NoMobs(), Clear(8)) + RESOURCES + (MoveLadder((8, 7)), GateAt((0,), 3), Mobs("zombie", 3, 7, 10)),
         terms=(stage("ipick", "done.make_iron_pickaxe >= 1", 0.25, "for an iron pickaxe"),
                stage("isword", "done.make_iron_sword >= 1", 0.25, "for an iron sword"),
                stage("gate", "kills.monsters >= 3", 0.25, "for opening the ladder"),
                stage("down", "level >= 1", 0.25, "for descending")),
         success="done.make_iron_pickaxe >= 1 and done.make_iron_sword >= 1 and level >= 1")
scenario(name="night-horde-no-shelter", horizon=180, time=DUSK, kit=dict(sword=2, torches=2, stone=1),
         topics=("fight", "torch"), objective="Night falls in 5 turns on open ground: fight and survive.",
         edits=(Clear(7), Scatter(B.TREE, 10, 4, 9), Mobs("zombie", 1, 6, 9), Mobs("skeleton", 1, 6, 9)),
         terms=(stage("k2", "kills.monsters >= 2", 0.2, "at 2 kills"), stage("k4", "kills.monsters >= 4", 0.2, "at 4 kills"),
                stage("n40", "night >= 40", 0.2, "after 40 night turns"), stage("n80", "night >= 80", 0.2, "after 80"),
                stage("end", "turn >= 180", 0.2, "for being alive at the end")), success="")
scenario(name="xp-attribute-spend", horizon=220, settings=ARENA, kit=dict(sword=3), player=dict(player_xp=2),
         topics=("fight", "attributes"),
         objective="Spend your 2 XP on strength (LEVEL_UP_STRENGTH twice); then a knight comes: kill it.",
         edits=(Clear(6), Mobs("zombie", 2, 4, 6)),
         events=(Event("str >= 3", (Mobs("knight", 1, 4, 7),), "A knight arrives."),),
         terms=(stage("s2", "str >= 2", 0.25, "at strength 2"), stage("s3", "str >= 3", 0.25, "at strength 3"),
                stage("knight", "kills.knight >= 1", 0.5, "for killing the knight")), success="kills.knight >= 1")
scenario(name="bow-kite-hard", horizon=180, settings=ARENA, kit=dict(bow=1, arrows=6, sword=1, wood=5, stone=5),
         topics=("fight", "craft"), objective="Kill 5 skeletons with 6 arrows and a wood sword; make more arrows at the table.",
         edits=(Clear(7), Scatter(B.TREE, 10, 4, 8), Stamp(B.CRAFTING_TABLE, ((0, 1),)), Stamp(B.FURNACE, ((1, 0),)),
                Mobs("skeleton", 5, 4, 8)),
         terms=(kills("skeleton", 5, 1.0, "skeleton"),), success="kills.skeleton >= 5")
scenario(name="enchant-choice", horizon=180, floor=6, settings=ARENA,
         kit=dict(sword=4, ruby=1, sapphire=1, armour=ARMOUR_DIAMOND),
         player=dict(player_mana=9, armour_enchantments=(1, 1, 1, 1)),
         topics=("fight", "magic"),
         objective="Fire elementals resist fire: enchant your sword with ice (the ice table takes a sapphire), then kill both.",
         edits=(NoMobs(), Clear(9), Stamp(B.ENCHANTMENT_TABLE_FIRE, ((0, 4),)), Stamp(B.ENCHANTMENT_TABLE_ICE, ((4, 0),)),
                Mobs("fire elemental", 2, 6, 8)),
         terms=(stage("ice", "enchant.sword >= 2", 0.5, "for an ice-enchanted sword"),
                kills("fire elemental", 2, 0.5, "fire elemental")),
         success="enchant.sword >= 2 and kills.monsters >= 2")
DIAMONDS = (Stamp(B.DIAMOND, tuple((-6, c) for c in range(-3, 3)) + tuple((6, c) for c in range(-2, 2))),)
scenario(name="diamond-gear-descend", horizon=500, settings=ARENA, topics=("craft", "fight", "floors"),
         objective="Make a diamond pickaxe, a diamond sword and a diamond armour piece, kill 2 monsters, DESCEND.",
         edits=(NoMobs(), Clear(8)) + RESOURCES + DIAMONDS + (MoveLadder((8, 7)), GateAt((0,), 2), Mobs("zombie", 2, 8, 10),
                                                                 Mobs("cow", 2, 5, 8)),
         terms=(stage("dpick", "done.make_diamond_pickaxe >= 1", 0.2, "for a diamond pickaxe"),
                stage("dsword", "done.make_diamond_sword >= 1", 0.2, "for a diamond sword"),
                stage("darmour", "done.make_diamond_armour >= 1", 0.2, "for a diamond armour piece"),
                stage("gate", "kills.monsters >= 2", 0.2, "for opening the ladder"),
                stage("down", "level >= 1", 0.2, "for descending")),
         success="done.make_diamond_pickaxe >= 1 and done.make_diamond_sword >= 1 and done.make_diamond_armour >= 1"
                 " and level >= 1")
