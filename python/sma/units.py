"""Units: the one place of the Celsius offset on the Python side (edp/lib/units.idp is the
scripts'). Every data file (CSV, VTU, JSON) is in SI units, temperatures in kelvin; the pictures
and the console in degrees C and MPa (docs/outputs.md)."""

KELVIN_AT_0C = 273.15


def celsius(kelvin):
    """A temperature in degrees C from kelvin (a number or a numpy array)."""
    return kelvin - KELVIN_AT_0C
