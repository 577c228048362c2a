"""Units: the one place of the Celsius offset on the Python side (edp/lib/units.idp is the
scripts'). Every data file (CSV, VTU, JSON) is in SI units, temperatures in kelvin; the pictures
and the console in degrees C and MPa (docs/outputs.md)."""

import re

KELVIN_AT_0C = 273.15
# A temperature written with its unit, as a temperature option takes it (edp/lib/errors.idp
# KelvinWord): a decimal number ended by C or K ("20C", "293.15K").
_WITH_UNIT = re.compile(r"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)([CcKk])")


def celsius(kelvin):
    """A temperature in degrees C from kelvin (a number or a numpy array)."""
    return kelvin - KELVIN_AT_0C


def temperature_word(text):
    """(number text, "C" or "K") of a temperature written with its unit ("20C" -> ("20", "C")),
    or None for any other word (a bare number is kelvin: not this form)."""
    m = _WITH_UNIT.fullmatch(text.strip())
    return (m.group(1), m.group(4).upper()) if m else None


def kelvin_of_word(text):
    """The kelvin value of a temperature written with its unit, or None (temperature_word)."""
    word = temperature_word(text)
    if word is None:
        return None
    return float(word[0]) + (KELVIN_AT_0C if word[1] == "C" else 0.0)
