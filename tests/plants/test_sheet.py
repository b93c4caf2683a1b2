"""The contact sheet of the plant library: every state of a crop on one labelled image,
rendered headless in real bpy."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from agrirecipe import ConfigurationError
from agrirecipe.cli import main
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.plants import contact_sheet
from agrirecipe.plants._sheet import _HEADER_PX, _LABEL_PX, sheet_keys

pytest.importorskip("bpy")
pytestmark = pytest.mark.slow


def test_sheet_rows_are_crops_and_columns_every_state(knowledge: KnowledgeBase) -> None:
    rows = sheet_keys(knowledge, ["Lettuce", "Apple"])
    assert [row[0].crop for row in rows] == ["Apple", "Lettuce"]  # catalogue order
    for row in rows:
        assert len({key.variety for key in row}) == 1
        assert len({(k.stage, k.season, k.health) for k in row}) == 3 * 4 * 2
    (pink,) = sheet_keys(knowledge, ["Apple"], variety="Fuji")
    assert {key.variety for key in pink} == {"Fuji"}
    with pytest.raises(ConfigurationError, match="no catalogue asset matches"):
        sheet_keys(knowledge, ["Apple"], variety="Cavendish")


def test_every_cell_shows_a_plant(tmp_path: Path, knowledge: KnowledgeBase) -> None:
    cell = 60
    path = contact_sheet(
        tmp_path / "sheet.png", knowledge=knowledge, crops=["Lettuce"], cell_px=cell
    )
    image = np.asarray(Image.open(path).convert("RGB")).astype(float)
    assert image.shape == (_HEADER_PX + cell, _LABEL_PX + 24 * cell, 3)
    background = image[_HEADER_PX + 2, _LABEL_PX + 2]
    for column in range(24):
        region = image[_HEADER_PX : _HEADER_PX + cell, _LABEL_PX + column * cell :][:, :cell]
        differs = np.abs(region - background).sum(axis=2) > 60
        assert differs.mean() > 0.01, f"cell {column} is empty"
    # the labels are drawn on white: the header holds dark text
    assert image[:_HEADER_PX, _LABEL_PX:].min() < 100
    assert not list(tmp_path.glob(".*"))  # written atomically


def test_cli_sheet_and_bad_output(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["assets", "sheet", "--crop", "Onion", "--cell", "50", "-o", str(tmp_path / "s.png")]
    )
    assert code == 0 and (tmp_path / "s.png").is_file()
    assert "wrote" in capsys.readouterr().out
    with pytest.raises(ConfigurationError, match=r"not a \.png"):
        contact_sheet(tmp_path / "sheet.jpg", crops=["Onion"])
