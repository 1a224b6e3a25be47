"""arcade.rooms: the room map the multi-room games carry in their HUD."""

import pytest

from glyphbench_rl.games.arcade.rooms import RoomMap


def test_map_marks_here_visited_unvisited_and_no_room():
    m = RoomMap(["-#-", "###"])
    assert m.enter(0, 1) is True
    assert m.hud() == "Map -@-/???"
    assert m.enter(1, 0) is True and m.enter(1, 1) is True
    assert m.hud() == "Map -+-/+@?"
    assert m.enter(0, 1) is False            # a second visit is no discovery
    assert m.hud() == "Map -@-/++?"
    assert (1, 2) in m and (0, 0) not in m


def test_long_world_shows_a_window_around_the_player():
    m = RoomMap(["#" * 20], span=2)
    m.enter(0, 0)
    assert m.hud() == "Map @??"
    m.enter(0, 10)
    assert m.hud() == "Map ??@??"
    m.enter(0, 19)
    assert m.hud() == "Map ??@"


def test_entering_a_missing_room_or_an_empty_layout_is_refused():
    m = RoomMap(["#-"])
    with pytest.raises(ValueError, match="no room at row 0, column 1"):
        m.enter(0, 1)
    with pytest.raises(ValueError, match="at least one room"):
        RoomMap(["--"])
