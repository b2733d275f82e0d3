"""The key of a run: a SHA-256 of every input that affects its result.

A run's result (histories and metrics) depends on

* the system's numbers as the compiled equations see them: the parameter vector
  (:meth:`SlingSystem.parameters`: masses, inertia, geometry, areas, cable, carrier, air
  density, gravity, cut-off), every aerodynamic table (:meth:`SlingSystem.tables`), the
  airspeed, density altitude, parachute model and restrictions;
* the manoeuvre: every field of its trajectory, wind (gust, ramp), disturbance and start;
* the run settings: length, step and sampling interval;
* the code that turns those into results: the source of the physical models
  (``slingloads/models``), of the multibody analyses and of the campaign's per-run work
  (metrics, the verdicts and the modes identified on a response, batch worker, this module),
  and the package version.

So an edited input changes the key of exactly the runs it affects, and a new version of the
physics invalidates every stored result. Names (the run id, the system's name) are not in the
key: renumbering a matrix does not re-run anything.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from functools import lru_cache
from pathlib import Path

import numpy as np

import slingloads
from slingloads.errors import InputError

#: Version of the stored result's layout: raise it when the per-run record changes.
RECORD_VERSION = 1


def _array(a):
    a = np.ascontiguousarray(a)
    return {"dtype": a.dtype.str, "shape": list(a.shape),
            "sha256": hashlib.sha256(a.tobytes()).hexdigest()}


def canonical(obj):
    """A JSON-able structure that identifies ``obj`` by value (floats exactly, arrays by
    digest). Dataclasses give their type name and fields.

    Parameters
    ----------
    obj : object
        None, bool, str, number, array, sequence, mapping or dataclass.

    Returns
    -------
    object
        Built of None, bool, str, int, lists and dicts (floats as their hex text).

    Raises
    ------
    InputError
        For an object it cannot describe by value.
    """
    if obj is None or isinstance(obj, (bool, str)):
        return obj
    if isinstance(obj, (int, np.integer)):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        return float(obj).hex()
    if isinstance(obj, np.ndarray):
        return {"array": _array(obj)}
    if isinstance(obj, (list, tuple)):
        return [canonical(v) for v in obj]
    if isinstance(obj, dict):
        return {str(k): canonical(obj[k]) for k in sorted(obj, key=str)}
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        out = {"type": f"{type(obj).__module__}.{type(obj).__qualname__}"}
        for f in dataclasses.fields(obj):
            out[f.name] = canonical(getattr(obj, f.name))
        return out
    raise InputError("a campaign input cannot be identified by value for the run cache",
                     type(obj).__name__)


@lru_cache(maxsize=1)
def code_digest():
    """SHA-256 of the package version and of the source files the results depend on.

    Returns
    -------
    str
        Hex digest.
    """
    root = Path(slingloads.__file__).resolve().parent
    files = sorted((root / "models").rglob("*.py")) + sorted(
        (root / "analyses" / "multibody").rglob("*.py")) + [
        root / "analyses" / "campaign" / "metrics.py", root / "analyses" / "verdicts.py",
        root / "analyses" / "response_modes.py",
        root / "analyses" / "campaign" / "worker.py", Path(__file__).resolve()]
    h = hashlib.sha256(slingloads.__version__.encode())
    h.update(str(RECORD_VERSION).encode())
    for path in files:
        h.update(path.relative_to(root).as_posix().encode())
        h.update(path.read_bytes())
    return h.hexdigest()


class KeyMaker:
    """Keys of runs; table digests are computed once per table object.

    Parameters
    ----------
    settings : mapping
        The run settings the keys include (:meth:`~.campaign.RunSettings.as_dict`).
    """

    def __init__(self, settings):
        self._settings = canonical(dict(settings))
        self._tables = {}

    def _table_digest(self, system):
        key = system.table_key()
        if key not in self._tables:
            h = hashlib.sha256()
            for array in system.tables():
                h.update(json.dumps(_array(np.asarray(array))).encode())
            self._tables[key] = (h.hexdigest(), system)  # the system keeps the ids alive
        return self._tables[key][0]

    def key(self, system, manoeuvre):
        """SHA-256 (hex) of one run (module notes).

        Parameters
        ----------
        system : SlingSystem
        manoeuvre : Manoeuvre

        Returns
        -------
        str
            Hex digest.
        """
        payload = {
            "code": code_digest(),
            "parameters": _array(system.parameters(locks=system.locks)),
            "tables": self._table_digest(system),
            "airspeed": float(system.airspeed).hex(),
            "density altitude": float(system.density_altitude).hex(),
            "parachute": system.chute_kind,
            "restrict": list(system.restrict),
            "manoeuvre": canonical(dataclasses.replace(manoeuvre, name="")),
            "settings": self._settings,
        }
        text = json.dumps(payload, sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()
