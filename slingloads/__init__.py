"""slingloads: a helicopter carried as a sling load under another rotorcraft.

Structural loads (CS-29.865 hook loads, aerodynamics, parachute drag, inertia relief, shear
force and bending moment), the lateral-step pendulum and the drogue-parachute sizing.
"""

__version__ = "0.1.0"
