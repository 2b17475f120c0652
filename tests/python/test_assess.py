"""assess() is `swarmdesign assess`: the same document, bit for bit."""

import json

import pytest

import swarmdesign as sd
from conftest import RANDOM_WALK, run_cli
from flavours import FLAVOUR_SOFTWARE


def test_assess_is_the_cli_assessment():
    chocolate = FLAVOUR_SOFTWARE["chocolate"]
    cli = json.loads(run_cli("assess", "--mission", "aac", "--pseudo-reality", "iridia-transfer", "--samples", "1-3",
                             "--seeds", "1-4", "--software", RANDOM_WALK, "--software", chocolate, "--json"))
    ours = sd.assess("aac", [RANDOM_WALK, chocolate], "iridia-transfer", samples="1-3", seeds="1-4")
    for document in (cli, ours.document):
        document.pop("seconds")
    assert ours.document == cli
    assert len(ours.summary) == 2 and len(ours.scores) == 2 * 4 * (1 + 3)


def test_assess_refusals():
    with pytest.raises(sd.InvalidRequestError):
        sd.assess("aac", RANDOM_WALK, "no-such-pseudo-reality", samples=1, seeds=1)
    with pytest.raises(sd.InvalidRequestError):
        sd.assess("aac", RANDOM_WALK, samples=0, seeds=1)
    with pytest.raises(sd.InvalidRequestError):
        sd.assess("aac", [], samples=1, seeds=1)
    with pytest.raises(TypeError):
        sd.assess("aac", RANDOM_WALK, samples=1.5, seeds=1)
