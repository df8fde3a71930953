"""Sweep specs: parsing, refusals that name the field, sampling and case keys."""

import itertools
import textwrap

import numpy as np
import pytest

from juncture.errors import SpecError
from juncture.study import load_spec
from support import EXAMPLE_DECK

ROOT = EXAMPLE_DECK.parent


def _spec(tmp_path, body, name="s.toml"):
    path = tmp_path / name
    path.write_text(f'base = "{EXAMPLE_DECK}"\n' + textwrap.dedent(body))
    return load_spec(path)


GRID = """
[complete]
keep_area = true
[analysis]
mach = [1.6, 1.2]
[parameters.z]
component = "wing"
field = "z"
mode = "offset"
range = [-1.0, 1.0, 5]
[parameters.fillet]
option = "fillet"
values = ["none", "cubic"]
[parameters.mach]
analysis = "mach"
values = [2.0, 1.6]
"""


def test_bundled_example_spec_is_the_documented_1000_cases():
    spec = load_spec(ROOT / "sweep_transport.toml")
    cases = spec.cases()
    assert len(cases) == 1000 and spec.base.samefile(EXAMPLE_DECK)
    assert [p.name for p in spec.parameters] == ["wing_z", "sweep", "fillet"]
    assert len({spec.key(c) for c in cases}) == 1000
    assert spec.machs == [1.2, 1.6, 2.0]


def test_grid_is_every_combination_first_parameter_slowest(tmp_path):
    spec = _spec(tmp_path, GRID)
    cases = spec.cases()
    expected = list(itertools.product(np.linspace(-1, 1, 5), ["none", "cubic"], [2.0, 1.6]))
    assert [tuple(c.values()) for c in cases] == expected
    assert spec.machs == [1.2, 1.6, 2.0]  # the analysis list and the parameter's values


def test_keys_depend_on_inputs_only(tmp_path):
    a = _spec(tmp_path, GRID)
    keys = [a.key(c) for c in a.cases()]
    assert len(set(keys)) == len(keys) and all(len(k) == 16 for k in keys)
    # the same inputs in another file, parameters in another order of cases: same keys
    b = _spec(tmp_path, GRID.replace("range = [-1.0, 1.0, 5]", "values = [1.0, -1.0]"), "b.toml")
    for case in b.cases():
        assert b.key(case) in keys
    # a changed fixed option or base changes every key
    c = _spec(tmp_path, GRID.replace("keep_area = true", "keep_area = false"), "c.toml")
    assert not set(c.key(x) for x in c.cases()) & set(keys)
    other = tmp_path / "deck.inp"
    other.write_bytes(EXAMPLE_DECK.read_bytes() + b"\n")
    d = _spec(tmp_path, GRID.replace(f'base = "{EXAMPLE_DECK}"', ""), "d.toml")
    d2 = load_spec(_rebased(tmp_path, GRID, other))
    assert not {d2.key(x) for x in d2.cases()} & {d.key(x) for x in d.cases()}


def _rebased(tmp_path, body, base):
    path = tmp_path / "rebased.toml"
    path.write_text(f'base = "{base}"\n' + textwrap.dedent(body))
    return path


@pytest.mark.parametrize("method", ["random", "lhs"])
def test_sampling_is_reproducible_and_in_bounds(tmp_path, method):
    body = f"""
    [sampling]
    method = "{method}"
    n = 40
    seed = 3
    [parameters.sweep]
    component = "wing"
    field = "sweep"
    mode = "offset"
    bounds = [-5.0, 5.0]
    [parameters.fillet]
    option = "fillet"
    values = ["none", "cubic", "circular"]
    """
    a, b = _spec(tmp_path, body).cases(), _spec(tmp_path, body, "b.toml").cases()
    assert a == b and len(a) == 40
    sweep = np.array([c["sweep"] for c in a])
    assert sweep.min() >= -5.0 and sweep.max() <= 5.0
    assert {c["fillet"] for c in a} == {"none", "cubic", "circular"}
    if method == "lhs":  # one sample in each of the n equal strata of every parameter
        strata = np.floor((sweep + 5.0) / 10.0 * 40).astype(int)
        assert sorted(strata) == list(range(40))
    c = _spec(tmp_path, body.replace("seed = 3", "seed = 4"), "c.toml").cases()
    assert c != a


BAD = [
    ("[parameters.z]\ncomponent = 'wing'\nfield = 'height'\nvalues = [1.0]\n",
     r"\[parameters.z\]: field: expected one of .*found 'height'"),
    ("[parameters.z]\ncomponent = 'wing'\nfield = 'sweep'\nmode = 'scale'\nvalues = [1.0]\n",
     r"mode: field 'sweep' takes offset, set, found 'scale'"),
    ("[parameters.z]\ncomponent = 'wing'\nfield = 'z'\nvalues = ['up']\n",
     r"values: expected numbers, found 'up'"),
    ("[parameters.z]\ncomponent = 'wing'\nfield = 'z'\nbounds = [0.0, 1.0]\n",
     r"bounds need random or lhs sampling"),
    ("[parameters.f]\noption = 'fillet'\nvalues = ['round']\n",
     r"option fillet: expected 'none', 'cubic' or 'circular', found 'round'"),
    ("[parameters.f]\noption = 'theta_u_deg'\nvalues = [120.0]\n", r"theta_u_deg"),
    ("[parameters.f]\noption = 'colour'\nvalues = [1]\n", r"colour: no such option"),
    ("[analysis]\nmach = [0.8]\n", r"\[analysis\] mach: expected a Mach number >= 1"),
    ("[analysis]\nn_x = 2\n", r"n_x: expected an integer >= 3"),
    ("[sampling]\nmethod = 'lhs'\n", r"'lhs' sampling needs the number of cases"),
    ("[parameters.z]\ncomponent = 'wing'\noption = 'fillet'\nvalues = [1]\n",
     r"give exactly one of component \(with field\), option or analysis"),
    ("colour = 3\n", r"unknown key 'colour'"),
    ("[parameters.z]\ncomponent = 'wing'\nfield = 'z'\nrange = [0, 1]\n",
     r"range: expected \[start, stop, count\]"),
]


@pytest.mark.parametrize("body, match", BAD)
def test_bad_specs_name_the_file_and_the_field(tmp_path, body, match):
    with pytest.raises(SpecError, match=match) as err:
        _spec(tmp_path, body)
    assert str(tmp_path / "s.toml") in str(err.value)


def test_unreadable_specs(tmp_path):
    with pytest.raises(SpecError, match="no such file"):
        load_spec(_rebased(tmp_path, "", tmp_path / "missing.inp"))
    bad = tmp_path / "bad.toml"
    bad.write_text("base = \n")
    with pytest.raises(SpecError, match="bad.toml: invalid TOML.*line 1"):
        load_spec(bad)
    with pytest.raises(SpecError, match="cannot read the sweep spec"):
        load_spec(tmp_path / "nope.toml")
