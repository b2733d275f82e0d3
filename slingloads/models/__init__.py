"""Physical models: atmosphere, airframe mass model, load sharing, aerodynamics, parachute.

Everything here works in SI units and never reads or writes files.
"""
