"""Missions and control software: the CLI's catalogue, parser, listings and drawings."""

import json
import xml.etree.ElementTree as ElementTree

import pytest

import swarmdesign as sd
from conftest import RANDOM_WALK, run_cli
from flavours import FLAVOUR_SOFTWARE, LEGACY


def test_catalogue_as_the_cli_lists_it():
    assert sd.missions() == json.loads(run_cli("missions", "--json"))
    catalogue = sd.module_catalogue()
    assert isinstance(catalogue, dict) and catalogue


def test_mission_objects():
    aac = sd.Mission.builtin("aac")
    assert (aac.name, aac.robots, aac.ticks, aac.direction) == ("aac", 20, 1200, "maximize")
    assert aac.document() == json.loads(run_cli("mission", "show", "aac", "--json"))
    ElementTree.fromstring(aac.svg())
    again = sd.Mission.from_json(aac.text)
    assert again.digest == aac.digest
    assert "aac" in repr(aac)


def test_mission_load_reads_files_only(tmp_path):
    source = tmp_path / "mine.json"
    source.write_text(sd.Mission.builtin("aac").text)
    assert sd.Mission.load(str(source)).digest == sd.Mission.builtin("aac").digest
    # A pathlib.Path, as evaluate, trace and design take one (issue #54).
    assert sd.Mission.load(source).digest == sd.Mission.builtin("aac").digest
    assert sd.Mission.named(source).digest == sd.Mission.builtin("aac").digest
    with pytest.raises(sd.MissionError):
        sd.Mission.load("aac")  # ./aac: no such file, never the catalogue's aac
    with pytest.raises(sd.MissionError):
        sd.Mission.builtin(str(source))


@pytest.mark.parametrize("flavour", sorted(FLAVOUR_SOFTWARE))
def test_every_flavour_reads_and_prints_as_the_cli(flavour):
    text = FLAVOUR_SOFTWARE[flavour]
    software = sd.ControlSoftware.parse(text)
    assert software.to_string() == run_cli("show-config", "--canonical", *text.split()).strip()
    listing = run_cli("show-config", *text.split())
    assert listing == software.describe() + "  " + software.to_string() + "\n"
    assert software.dot() == run_cli("show-config", "--dot", *text.split())
    assert sd.ControlSoftware.parse(software.to_string()) == software
    ElementTree.fromstring(software.svg())
    assert software.document()["architecture"] == software.architecture


@pytest.mark.parametrize("flavour,text", sorted(LEGACY.items()))
def test_legacy_strings(flavour, text):
    software = sd.ControlSoftware.parse(text, legacy_flavour=flavour)
    assert software.to_string() == run_cli("show-config", "--canonical", "--legacy-flavour", flavour, *text.split()).strip()
    legacy, exported_flavour, reader = software.to_legacy(flavour)
    assert exported_flavour == flavour and reader
    assert sd.ControlSoftware.parse(legacy, legacy_flavour=flavour) == software


def test_export_refusal_is_an_export_error():
    arlequin = sd.ControlSoftware.parse(FLAVOUR_SOFTWARE["arlequin"])
    with pytest.raises(sd.ExportError):
        arlequin.to_legacy("chocolate")


def test_software_values():
    a = sd.ControlSoftware.parse(RANDOM_WALK)
    b = sd.ControlSoftware.parse(RANDOM_WALK + " ")
    assert a == b and hash(a) == hash(b) and {a, b} == {a}
    assert str(a) == RANDOM_WALK and a.architecture == "fsm"


def test_help_shows_docstrings():
    assert "bits" in sd.evaluate.__doc__
    assert "Iterated F-Race" in sd.design.__doc__
    assert sd.ControlSoftware.parse.__doc__
