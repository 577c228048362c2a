"""Units: the one place of the Celsius offset on the Python side (edp/lib/units.idp is the
scripts'). The result files are in kelvin except where a column's name ends in _C."""

KELVIN_AT_0C = 273.15


def celsius(kelvin):
    return kelvin - KELVIN_AT_0C
