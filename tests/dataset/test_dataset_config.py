"""Dataset settings: weed densities and camera rigs from dataset.yaml, with overrides."""

from __future__ import annotations

import pytest

from agrirecipe import ConfigurationError
from agrirecipe.dataset import CameraRigs, DroneRig, dataset_defaults, parse_weed_density


@pytest.mark.parametrize(
    ("text", "density"),
    [("0.5/m2", 0.5), ("2", 2.0), (" 1.5 /m2 ", 1.5), ("some", 0.5), ("few", 0.2), (None, 0.0)],
)
def test_weed_densities_are_read_from_numbers_units_and_words(
    text: str | None, density: float
) -> None:
    assert parse_weed_density(text) == pytest.approx(density)


@pytest.mark.parametrize("text", ["lots", "-1", "0.5/ha", "1e9"])
def test_unknown_weed_densities_are_configuration_errors(text: str) -> None:
    with pytest.raises(ConfigurationError) as error:
        parse_weed_density(text)
    assert error.value.stage == "dataset"


def test_rigs_default_to_the_yaml_and_take_overrides() -> None:
    yaml_cameras = dataset_defaults()["cameras"]
    rigs = CameraRigs.defaults()
    assert rigs.robot.height_m == yaml_cameras["robot"]["height_m"]
    assert rigs.drone.altitude_m == yaml_cameras["drone"]["altitude_m"]
    changed = rigs.with_overrides(robot_height_m=0.4, drone_gsd_m=0.01, drone_view="oblique")
    assert changed.robot.height_m == 0.4
    assert changed.drone.gsd_m == 0.01
    assert changed.drone.view == "oblique"
    assert changed.overview == rigs.overview
    assert rigs.with_overrides(robot_height_m=None) == rigs


def test_bad_rig_settings_are_configuration_errors() -> None:
    with pytest.raises(ConfigurationError, match="altitude"):
        DroneRig(altitude_m=-3.0)
    with pytest.raises(ConfigurationError, match="unknown camera setting"):
        CameraRigs.defaults().with_overrides(robot_wheels=4)


@pytest.mark.parametrize(
    ("prompt", "density"),
    [
        ("a carrot field with some weeds", 0.5),
        ("a weedy carrot field", 2.0),
        ("carrots with lots of weeds", 2.0),
        ("carrots with a few weeds", 0.2),
        ("a weed-free carrot field", 0.0),
        ("carrots without weeds", 0.0),
        ("a carrot field", None),
    ],
)
def test_prompts_can_ask_for_weeds(prompt: str, density: float | None) -> None:
    from agrirecipe.dataset import weeds_in_prompt

    assert weeds_in_prompt(prompt) == density
