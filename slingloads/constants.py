"""Physical constants and exact unit factors to SI, for the physics (no unit library).

The models and analyses compute in SI; the few imperial quantities they name (a knot of
airspeed, a foot of rope, a pound of weight) use these exact definitions. Unit strings from
workbooks and reports are parsed at the boundary by :mod:`slingloads.io.common.units`.
"""

#: Standard gravity [m/s^2] (ICAO Doc 7488/3).
G0 = 9.80665
#: One knot [m/s].
KNOT = 1852.0 / 3600.0
#: One foot [m].
FOOT = 0.3048
#: One inch [m].
INCH = 0.0254
#: One pound mass [kg].
POUND = 0.45359237
#: One pound force [N].
POUND_FORCE = POUND * G0
