"""Fixed-field card reading and writing (juncture.io._cards): Fortran F7.0 / I3 semantics."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import DeckError, JunctureError, JunctureWarning
from juncture.io._cards import CardReader, format_card, format_ints, format_real, split_lines


def _reals(text, n, card="X", **kw):
    return CardReader(text, **kw).reals(n, card)[0]


# -- reading single fields --------------------------------------------------------------------

@pytest.mark.parametrize("field, value", [
    ("   16.0", 16.0),
    ("     16", 16.0),          # no point: integer value
    ("16     ", 16.0),          # left-justified
    ("       ", 0.0),           # blank field is zero
    ("  -.5  ", -0.5),
    ("    +3.", 3.0),
    (" 1.5E2 ", 150.0),
    ("1.5e-03", 0.0015),
    ("1.1D+01", 11.0),          # Fortran double-precision exponent letter
    ("    1E5", 1.0e5),         # exponent without a point
    ("  -0.00", 0.0),
])
def test_real_field_values(field, value):
    np.testing.assert_array_equal(_reals(field + "    9.0\n", 2), [value, 9.0])


def test_fields_are_fixed_slices_so_numbers_may_touch():
    values = _reals("  100.0-12.500-1.2500 3.5E-1\n", 4)
    np.testing.assert_array_equal(values, [100.0, -12.5, -1.25, 0.35])


def test_short_line_and_blank_fields_read_as_zero():
    np.testing.assert_array_equal(_reals("    1.0\n", 3), [1.0, 0.0, 0.0])
    np.testing.assert_array_equal(_reals("           2.0\n", 3), [0.0, 2.0, 0.0])


def test_list_continues_on_a_second_card_and_columns_71_80_are_ignored():
    card1 = "".join(f"{v:7.1f}" for v in range(10)) + "  LABEL 99"
    card2 = f"{10.0:7.1f}{11.0:7.1f}" + " " * 56 + "  1234567x"
    np.testing.assert_array_equal(_reals(f"{card1}\n{card2}\n", 12), np.arange(12.0))


def test_embedded_blank_is_ignored_with_a_warning():
    with pytest.warns(JunctureWarning, match=r"line 1, columns 1-7: blanks inside the number "
                                             r"'1 2.5' \(X value 1\) ignored"):
        reader = CardReader(" 1 2.5\n")
        assert reader.reals(1, "X")[0][0] == 12.5
    assert len(reader.warnings) == 1


def test_letterless_fortran_exponent_is_read_with_a_warning():
    with pytest.warns(JunctureWarning, match=r"'1.5-2' \(X value 1\) read as 1.5E-2"):
        assert _reals("  1.5-2\n", 1)[0] == pytest.approx(0.015, rel=1e-15)


def test_crlf_trailing_blanks_and_blank_trailing_lines():
    assert split_lines("a  \r\nb\r\n\r\n") == ["a  ", "b", ""]
    reader = CardReader("    1.0   \r\n    2.0\r\n   \r\n\r\n")
    assert reader.end == 2
    np.testing.assert_array_equal(reader.reals(2, "X")[0], [1.0, 0.0])
    np.testing.assert_array_equal(reader.reals(1, "X")[0], [2.0])
    assert reader.at_end()


def test_integer_fields():
    reader = CardReader("  1 -1 12  7\n")
    line, text = reader.next_card("control")
    assert [reader.integer(text, line, a, a + 2, "J") for a in (1, 4, 7, 10, 13)] == \
        [1, -1, 12, 7, 0]


# -- reading faults ---------------------------------------------------------------------------

@pytest.mark.parametrize("field", ["  l2.5", "  1.2.3", "   inf", "   nan", "    1E", "   --1",
                                   "  0x1F", "   ,5"])
def test_malformed_number_is_an_error_naming_line_and_columns(field):
    text = "    1.0" + field.rjust(7) + "\n"
    with pytest.raises(DeckError, match=r"^line 1, columns 8-14: expected a number "
                                        r"\(WAFORG y for section 3\), found ") as err:
        CardReader(text).reals(2, "WAFORG", "for section 3", names=("x", "y"))
    assert err.value.line == 1 and err.value.columns == (8, 14)


def test_number_out_of_range_is_an_error():
    with pytest.raises(DeckError, match=r"columns 1-7: number out of range \(X value 1\)"):
        _reals("  9E999\n", 1)


def test_value_beyond_the_expected_count_is_an_error():
    with pytest.raises(DeckError, match=r"line 1, columns 22-28: expected 3 values on this XAF "
                                        r"card, found a 4th in columns 22-28: '150.0'"):
        CardReader("    0.0   50.0  100.0  150.0\n").reals(3, "XAF")


def test_end_of_file_inside_a_list_is_an_error():
    card = "    1.0" * 10 + "\n"
    with pytest.raises(DeckError, match=r"file ended after line 1 while reading WAFORD for "
                                        r"section 3 \(10 of 11 values read\)"):
        CardReader(card).reals(11, "WAFORD", "for section 3")


def test_tab_in_a_field_is_rejected():
    with pytest.raises(DeckError, match=r"line 1, columns 8-14: TAB character in column 8"):
        _reals("    1.0\t2.0\n", 2)


def test_tab_in_the_label_columns_is_ignored():
    assert _reals("    1.0" + " " * 65 + "\tXAF\n", 1)[0] == 1.0


def test_integer_field_faults():
    reader = CardReader("  1 1.\n")
    line, text = reader.next_card("control")
    with pytest.raises(DeckError, match=r"line 1, columns 4-6: expected an integer \(J1\), "
                                        r"found '1.'"):
        reader.integer(text, line, 4, 6, "J1")


# -- writing ----------------------------------------------------------------------------------

@pytest.mark.parametrize("value, text", [
    (100.0, "  100.0"),
    (16.0, "   16.0"),
    (314.16, " 314.16"),
    (0.1, "    0.1"),
    (-12.5, "  -12.5"),
    (-0.0125, " -.0125"),      # a leading blank beats the leading zero
    (0.0, "    0.0"),
    (-0.0, "   -0.0"),
    (1234567.0, "1234567"),    # no room for a point: integer value
    (1.0e7, "  1.0E7"),
    (1.5e-9, " 1.5E-9"),
    (1.23e-10, "123E-12"),
    (-1.0e-300, "-1E-300"),
])
def test_format_real_exact(value, text):
    assert format_real(value) == (text, True)


def test_format_real_inexact_gives_the_nearest_fitting_text():
    text, exact = format_real(1.0 / 3.0)
    assert not exact and len(text) == 7
    assert abs(float(text) - 1.0 / 3.0) < 1e-6


@pytest.mark.parametrize("value", [1.7976931348623157e308, -1.7894736842106206e308])
def test_format_real_near_overflow_stays_finite(value):
    text, exact = format_real(value)
    assert not exact and math.isfinite(float(text)) and float(text) == pytest.approx(value, 0.1)


def test_format_real_rejects_non_finite():
    with pytest.raises(JunctureError, match="non-finite"):
        format_real(float("nan"))


def test_format_card_lists_labels_and_precision_warning():
    lines = format_card(np.arange(12.0), "XAF")
    assert len(lines) == 2
    assert lines[0][:70] == "".join(f"{v:7.1f}" for v in range(10))
    assert lines[0][72:] == "XAF" and lines[1][72:] == "XAF"
    with pytest.warns(JunctureWarning, match=r"TZORD 2 = 0.3333333333333333 cannot be "
                                             r"written exactly in 7 columns"):
        format_card([1.0, 1.0 / 3.0], "TZORD 1", what="TZORD")


def test_format_ints_overflow():
    assert format_ints([1, -1, 12], 3) == "  1 -1 12"
    with pytest.raises(JunctureError, match=r"NX 2 = 12345 does not fit in 4 columns"):
        format_ints([1, 12345], 4, what="NX")


# -- properties -------------------------------------------------------------------------------

@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=-1e300, max_value=1e300))
def test_format_real_round_trips_or_says_so(value):
    text, exact = format_real(value)
    assert len(text) == 7
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the writer uses only plain forms
        back = _reals(text + "\n", 1)[0]
    if exact:
        assert back == value and math.copysign(1, back) == math.copysign(1, value)
    else:  # nearest text with p significant digits: error at most half a unit of the last one
        mantissa = text.strip().lstrip("-").split("E")[0].replace(".", "").lstrip("0")
        p = len(mantissa.rstrip("0")) or 1
        assert abs(back - value) <= 0.5 * 10.0 ** (1 - p) * abs(value) * (1 + 1e-12)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789", min_size=1, max_size=6), st.integers(0, 6),
       st.sampled_from(["", "-"]))
def test_any_seven_column_decimal_is_written_back_exactly(digits, point, sign):
    point = min(point, len(digits))
    text = (sign + digits[:point] + "." + digits[point:])[:7]
    if text in (".", "-."):
        return
    value = float(text)
    out, exact = format_real(value)
    assert exact and float(out) == value


def test_format_card_is_silent_on_float_noise_only():
    """An area through r = sqrt(A / pi) and back is 1-2 ulps off the deck's decimal: written
    as that decimal without a warning; a real loss of digits still warns."""
    from juncture.io._cards import NOISE_ULPS

    noisy = [np.pi * np.sqrt(a / np.pi) ** 2 for a in (1.9, 7.22, 60.6, 84.96, 110.09)]
    assert [float(v) for v in noisy] != [1.9, 7.22, 60.6, 84.96, 110.09]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        (line,) = format_card(noisy)
    assert [float(line[7 * i:7 * i + 7]) for i in range(5)] == [1.9, 7.22, 60.6, 84.96, 110.09]
    off = 1.9 + (NOISE_ULPS + 1) * math.ulp(1.9)
    with pytest.warns(JunctureWarning, match="cannot be written exactly"):
        format_card([off])
