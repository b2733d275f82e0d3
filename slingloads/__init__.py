"""slingloads: a helicopter carried as a sling load under another rotorcraft.

Structural loads (CS-29.865 hook loads, aerodynamics, parachute drag, inertia relief, shear
force and bending moment), the lateral-step pendulum and the drogue-parachute sizing.

The names below are importable from the package root (loaded on first use)::

    import slingloads as sl
    results = sl.run("loadcases/example-light-twin.xlsx")    # read, run every analysis asked
    results.loads.envelope()                                   # typed results, DataFrames
    sl.write_reports(results, "reports")                       # every report, all at once
"""

from importlib import import_module

__version__ = "0.1.0"

_EXPORTS = {
    "read_study": "slingloads.io.study",
    "run": "slingloads.io.study:run_workbook",
    "write_reports": "slingloads.io.reports",
    "Study": "slingloads.runs.study",
    "Results": "slingloads.runs.study",
    "WorkbookSource": "slingloads.io.study",
    "write_input_workbook": "slingloads.io.template",
    "write_loads_outputs": "slingloads.io.loads.report",
    "hook_angle_comparison": "slingloads.analyses.hook_angle",
    "MassItems": "slingloads.models.airframe",
    "Hardpoints": "slingloads.models.airframe",
    "Airframe": "slingloads.models.airframe",
    "FuselageAero": "slingloads.models.aerodynamics",
    "Fin": "slingloads.models.aerodynamics",
    "Parachute": "slingloads.models.parachute",
    "Table1D": "slingloads.models.aero_tables",
    "Table2D": "slingloads.models.aero_tables",
    "FlightCondition": "slingloads.models.flight",
    "SolverSettings": "slingloads.models.integration",
    "LoadsStudy": "slingloads.analyses.loads",
    "LoadsResult": "slingloads.analyses.loads",
    "AeroEnvelope": "slingloads.analyses.loads",
    "ListedCase": "slingloads.analyses.loads",
    "HookLoadOptions": "slingloads.analyses.hook_loads",
    "InputError": "slingloads.errors",
}

__all__ = ["__version__", *_EXPORTS]


def __getattr__(name):
    if name in _EXPORTS:
        module, _, attribute = _EXPORTS[name].partition(":")
        return getattr(import_module(module), attribute or name)
    raise AttributeError(f"module 'slingloads' has no attribute {name!r}")
