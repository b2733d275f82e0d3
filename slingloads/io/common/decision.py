"""The parachute decision's section: one table, the same in every report that mentions the
parachute (sizing, campaign, multibody, loads), in the report's unit system.

The decision itself is made once (:mod:`slingloads.analyses.parachute_decision`, kept in
``study.results.parachute_decision``); this module only prints it: :func:`decision_table`
converts its areas, :func:`decision_section` is the titled section every report shows, and
:func:`with_decision` gives a :class:`~slingloads.io.common.report_writer.ReportKind` whose
sheets take it.
"""

from __future__ import annotations

import dataclasses
import functools

from slingloads.io.common.excel import Section
from slingloads.io.common.report import in_report_units, report_unit
from slingloads.io.common.units import unit_label

TITLE = "Parachute decision"
NOTE = ("One decision, the same in every report that mentions the parachute "
        "(docs/parachute-sizing.md).")


def decision_table(decision, units="SI"):
    """The parachute decision's table in report units (areas converted), the same in every
    report that carries it."""
    frame = decision.to_frame()
    areas = frame["unit"] == "m^2"
    unit = unit_label(report_unit("area", units))
    frame.loc[areas, "value"] = [float(in_report_units(float(v), "area", units))
                                 for v in frame.loc[areas, "value"]]
    frame.loc[areas, "unit"] = unit
    return frame


def decision_section(decision, units="SI"):
    """The titled section of the decision (a list: empty when there is no decision)."""
    if decision is None:
        return []
    return [Section(TITLE, decision_table(decision, units), note=NOTE)]


def with_decision(kind, study):
    """``kind`` (a :class:`ReportKind` whose ``sheets`` takes ``decision=``) showing the
    study's parachute decision (``study.results.parachute_decision``), the one every report
    that mentions the parachute carries; ``kind`` itself when there is none."""
    decision = study.results.parachute_decision
    if decision is None:
        return kind
    return dataclasses.replace(kind, sheets=functools.partial(kind.sheets, decision=decision))
