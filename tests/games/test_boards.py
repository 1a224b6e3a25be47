import pytest

from glyphbench_rl.games.common.boards import Bits, cell_actions, cell_of


def mask(lines):
    return sum(1 << r * len(lines[0]) + c for r, line in enumerate(lines) for c, ch in enumerate(line) if ch == "#")


def test_grow_does_not_wrap_between_rows():
    bits = Bits(3, 4)
    assert bits.grow(mask(["...#", "....", "...."])) == mask(["..##", "...#", "...."])
    assert bits.grow(mask(["....", "#...", "...."])) == mask(["#...", "##..", "#..."])
    assert bits.grow8(mask(["....", "...#", "...."])) == mask(["..##", "..##", "..##"])


def test_flood_and_regions():
    bits = Bits(4, 4)
    allowed = mask(["##.#", "#..#", "..##", "#..."])
    assert bits.flood(1, allowed) == mask(["##..", "#...", "....", "...."])
    assert bits.flood8(1, allowed) == mask(["##..", "#...", "....", "...."])
    assert bits.flood8(1 << 3, allowed) == mask(["...#", "...#", "..##", "...."])
    # one flood for both neighbourhoods: the 8-connected fill is flood(..., diagonal=True)
    assert bits.flood(1 << 3, allowed, diagonal=True) == bits.flood8(1 << 3, allowed)
    assert bits.flood(1 << 3, allowed) == mask(["...#", "...#", "..##", "...."])
    assert bits.flood(1 << 15, allowed) == 0 and bits.flood(1 << 15, allowed, diagonal=True) == 0
    parts = list(bits.regions(allowed))
    assert sum(parts) == allowed and len(parts) == 3
    assert bits.cells(mask(["#...", "...#", "....", "...."])) == [(0, 0), (1, 3)]
    assert bits.row_bits(allowed, 2) == 0b1100 and bits.col_bits(allowed, 0) == 0b1011


def test_cell_actions_families():
    actions = cell_actions(2, 3, [("", "fill"), ("X", "mark")])
    assert actions.names == ("A1", "B1", "C1", "A2", "B2", "C2", "XA1", "XB1", "XC1", "XA2", "XB2", "XC2")
    assert cell_of(actions.index("XB2"), 3, 6) == (1, 1, 1)
    assert cell_of(actions.index("C1"), 3, 6) == (0, 0, 2)
    with pytest.raises(ValueError):
        cell_actions(2, 27, [("", "fill")])
