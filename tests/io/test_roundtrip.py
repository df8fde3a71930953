"""One write -> read round trip for every registered format that has a reader and a writer.

Each format states what it keeps and to what tolerance; the written object must come back
unchanged in what the format keeps, and the object given to the writer must not be mutated.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import juncture as jc
from juncture.geometry import Geometry

#: Formats with reader and writer that hold something other than surface networks.
EXCLUDED = {
    "wavedrag": "a wave-drag deck holds components (wing, fuselage, ...), not networks",
    "juncture": "the JSON model holds a Configuration (components), not networks",
}

#: Per format: file extension, writer options, absolute tolerance on coordinates, and what
#: survives (names, symmetry, title). All three text formats write Python repr (shortest
#: exact decimal), so the coordinates come back bit for bit.
SPEC = {
    "lawgs": dict(ext=".wgs", write={}, atol=0.0, names=True, symmetry=True, title=True),
    "hess": dict(ext=".hess", write={}, atol=0.0, names=True, symmetry=True, title=True),
    # Plot3D has no names or symmetry: write without images and compare block by block
    "plot3d": dict(ext=".p3d", write={"mirror": False}, atol=0.0, names=False, symmetry=False,
                   title=False),
}


def _round_trip_formats():
    reg = jc.io
    both = sorted(set(reg.reader_formats()) & set(reg.writer_formats()))
    return [f for f in both if f not in EXCLUDED]


def _geometry():
    rng = np.random.default_rng(20240611)
    shapes = {"wing upper": (4, 7), "wing lower": (4, 7), "body upper": (9, 5),
              "fin 1 outboard": (2, 3), "pod 1": (6, 11), "nose": (1, 2)}
    nets = {}
    for k, (name, (nl, npt)) in enumerate(shapes.items()):
        base = np.stack(np.meshgrid(np.arange(npt) * 1.7, np.arange(nl) * 0.9, indexing="xy"),
                        axis=-1)
        z = np.full((nl, npt, 1), 0.3 * k)
        nets[name] = np.concatenate([base, z], axis=-1) * 10.0 ** (k - 2) + rng.normal(
            scale=0.01, size=(nl, npt, 3))
    return Geometry(networks=nets, title="round trip: six networks",
                    symmetry={"wing upper": "xz", "wing lower": "xz", "fin 1 outboard": "xy",
                              "pod 1": "yz"})


def _snapshot(geo):
    return ({k: np.array(v, copy=True) for k, v in geo.networks.items()}, dict(geo.symmetry),
            geo.title)


def write_read(fmt, obj, tmp_path, **extra):
    """Write ``obj`` in ``fmt``, read it back (format from content/extension), compare."""
    if fmt not in SPEC:
        pytest.fail(f"format {fmt!r} has a reader and a writer but no stated round-trip "
                    "tolerance: add it to SPEC (or to EXCLUDED with the reason)")
    spec = SPEC[fmt]
    geo = jc.io.to_geometry(obj)
    before = _snapshot(geo)
    raw_before = ({k: np.array(v, copy=True) for k, v in obj.items()}
                  if isinstance(obj, dict) else None)
    path = tmp_path / f"rt{spec['ext']}"
    jc.write(obj, path, format=fmt, **{**spec["write"], **extra})
    back = jc.read(path)
    again = jc.read(path, format=fmt)
    assert again.allclose(back, rtol=0, atol=0)
    # the input is unchanged
    nets, sym, title = before
    assert dict(geo.symmetry) == sym and geo.title == title
    for k, v in nets.items():
        np.testing.assert_array_equal(geo.networks[k], v)
    if raw_before is not None:
        for k, v in raw_before.items():
            np.testing.assert_array_equal(np.asarray(obj[k]), v)
    # what the format keeps
    if spec["names"]:
        assert list(back.networks) == list(geo.networks)
        pairs = [(back.networks[k], geo.networks[k]) for k in geo.networks]
    else:
        assert len(back.networks) == len(geo.networks)
        pairs = list(zip(back.networks.values(), geo.networks.values(), strict=True))
    for got, want in pairs:
        assert got.shape == want.shape
        np.testing.assert_allclose(got, want, rtol=0, atol=spec["atol"])
    if spec["symmetry"]:
        assert dict(back.symmetry) == dict(geo.symmetry)
    if spec["title"]:
        assert back.title == geo.title
    return back


def test_round_trip_formats_are_known():
    found = _round_trip_formats()
    assert {"lawgs", "hess", "plot3d"} <= set(found)
    for fmt in SPEC:
        assert fmt in found, f"{fmt} is in SPEC but no longer registered with reader and writer"


@pytest.mark.parametrize("fmt", _round_trip_formats())
def test_round_trip_geometry(tmp_path, fmt):
    write_read(fmt, _geometry(), tmp_path)


@pytest.mark.parametrize("fmt", _round_trip_formats())
def test_round_trip_dict_of_writable_arrays(tmp_path, fmt):
    rng = np.random.default_rng(1)
    nets = {"a": rng.normal(size=(3, 2, 3)), "b": rng.normal(size=(2, 5, 3))}
    write_read(fmt, nets, tmp_path)
    assert nets["a"].flags.writeable


@pytest.mark.parametrize("fmt", _round_trip_formats())
@given(net=arrays(float, st.tuples(st.integers(1, 3), st.integers(1, 4), st.just(3)),
                  elements=st.floats(-1e12, 1e12, allow_nan=False, allow_infinity=False,
                                     allow_subnormal=True)))
@settings(max_examples=15, deadline=None)
def test_round_trip_any_floats(tmp_path_factory, fmt, net):
    write_read(fmt, Geometry(networks={"n": net}), tmp_path_factory.mktemp(fmt))
