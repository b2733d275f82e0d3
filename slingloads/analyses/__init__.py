"""Analyses built on the physical models: CS-29.865 load cases, inertia relief, shear force and
bending moment, envelopes; the lateral-step pendulum; parachute sizing.

Everything here works in SI units and never reads or writes files.
"""
