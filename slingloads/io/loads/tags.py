"""Names of the six internal-load components in the loads report's titles and file names
(no plotting library needed to know them)."""

#: Titles of the components.
COMPONENT_TITLES = {
    "Vx": "X shear", "Vy": "Y shear", "Vz": "Z shear",
    "Mx": "X moment (torsion)", "My": "Y moment", "Mz": "Z moment",
}
#: File-name tags of the components (``<stem>-X_shear.png``).
COMPONENT_TAGS = {
    "Vx": "X_shear", "Vy": "Y_shear", "Vz": "Z_shear",
    "Mx": "X_moment", "My": "Y_moment", "Mz": "Z_moment",
}
