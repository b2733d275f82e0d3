"""A hook trajectory read from a CSV file (the io layer: it reads, the model checks).

The file has a header row and one row per breakpoint: ``time_s`` and one of three column
sets, in the multibody model's earth axes (X aft along the flight path, Y right, Z up),
relative to the steady flight:

* ``ax_mps2, ay_mps2, az_mps2``: acceleration, linear between breakpoints
  (:meth:`HookTrajectory.from_acceleration
  <slingloads.models.hook_trajectory.HookTrajectory.from_acceleration>`);
* ``vx_mps, vy_mps, vz_mps``: velocity, linear between breakpoints (``from_velocity``);
* ``x_m, y_m, z_m``: displacement, a cubic spline leaving the first sample at rest
  (``from_displacement``).

Example (a 1 m/s^2 pull down and to the right for 2 s, jerk-limited)::

    time_s,ax_mps2,ay_mps2,az_mps2
    0,0,0,0
    1,0,0.5,-1
    3,0,0.5,-1
    4,0,0,0
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from slingloads.errors import InputError
from slingloads.io.common.locate import located
from slingloads.limits import MAX_CSV_BYTES
from slingloads.models.hook_trajectory import HookTrajectory
from slingloads.safeopen import open_regular

#: The column sets a trajectory file may give, and the constructor each goes to.
COLUMN_SETS = {("ax_mps2", "ay_mps2", "az_mps2"): "from_acceleration",
               ("vx_mps", "vy_mps", "vz_mps"): "from_velocity",
               ("x_m", "y_m", "z_m"): "from_displacement"}


def read_trajectory_csv(path, *, from_hover=False):
    """A :class:`~slingloads.models.hook_trajectory.HookTrajectory` from a CSV file (module
    notes).

    Parameters
    ----------
    path : path-like
    from_hover : bool
        The runs start trimmed in hover.

    Returns
    -------
    HookTrajectory

    Raises
    ------
    InputError
        Naming the file (and the row and column of a bad value).
    """
    path = Path(path)
    try:
        with open_regular(path, MAX_CSV_BYTES, follow_links=True) as handle:
            frame = pd.read_csv(handle)
    except (OSError, ValueError) as error:
        raise InputError(f"cannot read the trajectory file: {error}", file=str(path)) from None
    columns = [c.strip() for c in frame.columns]
    frame.columns = columns
    found = [names for names in COLUMN_SETS if set(names) <= set(columns)]
    if "time_s" not in columns or len(found) != 1:
        raise InputError("a trajectory file needs the column time_s and one of the column "
                         f"sets {[list(n) for n in COLUMN_SETS]}; columns are", columns,
                         file=str(path))
    names = found[0]
    for column in ("time_s", *names):
        values = pd.to_numeric(frame[column], errors="coerce").to_numpy(float)
        bad = ~np.isfinite(values)
        if bad.any():
            row = int(np.argmax(bad))
            raise InputError(f"trajectory values must be finite numbers (column {column}, "
                             f"row {row + 2})", frame[column].iloc[row], file=str(path),
                             cell=f"{column}{row + 2}")
    time = frame["time_s"].to_numpy(float)
    values = frame[list(names)].to_numpy(float)
    build = getattr(HookTrajectory, COLUMN_SETS[names])
    with located(str(path)):
        return build(time, values, from_hover=from_hover, name=f"CSV file {path.name}")
