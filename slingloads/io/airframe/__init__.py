"""The airframe sheets every analysis reads: mass items, cut stations, hardpoints and the
aerodynamic tables of the fuselage, the fin and the parachute."""
