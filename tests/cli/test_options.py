"""``--resolver`` is the same list for every command that resolves prompts."""

from __future__ import annotations

import pytest

from agrirecipe.cli import build_parser
from agrirecipe.resolve import available_resolvers


@pytest.mark.parametrize(
    "command",
    [
        ["generate", "a wheat field", "-o", "out"],
        ["app"],
    ],
)
def test_every_builtin_strategy_is_accepted(command: list[str]) -> None:
    for name in available_resolvers():
        args = build_parser().parse_args([*command, "--resolver", name])
        assert args.resolver == name


def test_an_unknown_strategy_is_refused_by_the_parser(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        build_parser().parse_args(["generate", "a wheat field", "-o", "out", "--resolver", "gpt"])
    assert "finetuned" in capsys.readouterr().err
