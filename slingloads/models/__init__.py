"""Physical models: atmosphere, airframe mass model, load sharing, aerodynamics, parachute.

Everything here works in SI units and reads no user file (sample_aircraft reads the packaged
generic sample tables).
"""
