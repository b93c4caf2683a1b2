"""``agrirecipe assets``: list the catalogue, or parse an asset path back into attributes."""

from __future__ import annotations

import pytest

from agrirecipe.cli import main

PINK_LADY = (
    "/Game/Agriculture/Fruits/Apple/PinkLady/Maturation/Summer/Healthy/"
    "SM_Apple_PinkLady_Maturation_Summer_Healthy.SM_Apple_PinkLady_Maturation_Summer_Healthy"
)


def test_parse(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets", "--parse", PINK_LADY]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "category: Fruits",
        "crop: Apple",
        "variety: Pink Lady",
        "stage: Maturation",
        "season: Summer",
        "health: Healthy",
    ]


def test_parse_unknown_path_names_the_nearest(capsys: pytest.CaptureFixture[str]) -> None:
    typo = PINK_LADY.replace("PinkLady", "PinkLaddy")
    assert main(["assets", "--parse", typo]) == 2
    err = capsys.readouterr().err
    assert err.startswith("agrirecipe: error: ")
    assert f"nearest valid path: {PINK_LADY}" in err


def test_list_everything(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets"]) == 0
    paths = capsys.readouterr().out.splitlines()
    assert len(paths) == 1584
    assert len(set(paths)) == 1584
    assert PINK_LADY in paths


def test_list_one_crop(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets", "--crop", "Wheat"]) == 0
    paths = capsys.readouterr().out.splitlines()
    assert len(paths) == 4 * 3 * 4 * 2
    assert all(path.startswith("/Game/Agriculture/Cereals/Wheat/") for path in paths)


def test_unknown_crop(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets", "--crop", "Wheet"]) == 2
    assert "nearest: Wheat" in capsys.readouterr().err


def test_content_root(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets", "--crop", "Apple", "--content-root", "/Game/MyFarm/Crops/"]) == 0
    paths = capsys.readouterr().out.splitlines()
    assert paths[0].startswith("/Game/MyFarm/Crops/Fruits/Apple/PinkLady/")
    moved = PINK_LADY.replace("/Game/Agriculture/", "/Game/MyFarm/Crops/")
    assert main(["assets", "--content-root", "/Game/MyFarm/Crops", "--parse", moved]) == 0
    assert "variety: Pink Lady" in capsys.readouterr().out


def test_bad_content_root(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["assets", "--content-root", "Game/My Farm"]) == 2
    assert "is not an Unreal package path" in capsys.readouterr().err
