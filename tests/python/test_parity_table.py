"""docs/front-ends.md's table of capabilities x front ends cannot drift from the code (issue
#54): every command it names answers --help, every route is in src/web/API.md, every Python
name exists, every other cell gives its one-line reason; and every CLI command and every
public method of sd.Account is in the table."""

import re
import subprocess

import pytest

import swarmdesign as sd
from conftest import BINARY, ROOT

TABLE = ROOT / "docs" / "front-ends.md"
API = ROOT / "src" / "web" / "API.md"
REFERENCE = re.compile(r"^`([^`]+)`")


def rows():
    out = []
    for line in TABLE.read_text().splitlines():
        if not line.startswith("| ") or line.startswith("| capability") or line.startswith("|---"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        assert len(cells) == 4, f"a row of four cells: {line}"
        out.append(cells)
    return out


def reference(cell):
    match = REFERENCE.match(cell)
    return match.group(1) if match else None


def test_every_cell_names_what_offers_it_or_says_why_not():
    table = rows()
    assert len(table) >= 30
    for capability, *cells in table:
        for cell in cells:
            if reference(cell) is None:
                assert cell.startswith("— ") and len(cell.split()) >= 4, f"{capability}: '{cell}' gives no reason"


def test_every_command_named_answers_help():
    if not BINARY.exists():
        pytest.skip(f"no swarmdesign binary at {BINARY}")
    for capability, cli, _, _ in rows():
        name = reference(cli)
        if name is None:
            continue
        words = name.split()
        assert words[0] == "swarmdesign", f"{capability}: {name}"
        process = subprocess.run([str(BINARY), *words[1:], "--help"], capture_output=True, text=True, timeout=60)
        assert process.returncode == 0, f"{capability}: {name} --help: {process.stderr}"


def test_every_route_named_is_in_the_api_reference():
    api = API.read_text()
    for capability, _, web, _ in rows():
        route = reference(web)
        if route is not None:
            assert re.match(r"^(GET|POST) /api/", route), f"{capability}: {route}"
            assert f"| `{route}`" in api, f"{capability}: {route} is not in src/web/API.md"


def test_every_python_name_exists():
    for capability, _, _, python in rows():
        name = reference(python)
        if name is None:
            continue
        parts = name.split(".")
        assert parts[0] == "sd", f"{capability}: {name}"
        obj = sd
        for part in parts[1:]:
            assert hasattr(obj, part), f"{capability}: {name} does not exist"
            obj = getattr(obj, part)


def test_every_command_and_account_method_has_its_row():
    if not BINARY.exists():
        pytest.skip(f"no swarmdesign binary at {BINARY}")
    text = TABLE.read_text()
    help_text = subprocess.run([str(BINARY), "--help"], capture_output=True, text=True, timeout=60).stdout
    commands = re.findall(r"^  ([a-z][a-z-]+)(?:, [a-zA-Z-]+)*\s", help_text.split("Subcommands:")[1], re.M)
    assert "run-design" in commands and "collect" in commands
    for command in commands:
        if command == "run-exp":  # web's first name, kept as an alias
            continue
        assert f"`swarmdesign {command}" in text, f"swarmdesign {command} has no row in docs/front-ends.md"
    for method in (m for m in vars(sd.Account) if not m.startswith("_")):
        assert f"`sd.Account.{method}`" in text, f"Account.{method} has no row in docs/front-ends.md"
