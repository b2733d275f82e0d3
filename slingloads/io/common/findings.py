"""The Findings sheet: the study's findings (:mod:`slingloads.runs.findings`), the same table
in every report of a run, in the report's unit system.

:func:`findings_sheet` makes the sheet from the one :class:`~slingloads.runs.findings.Findings`
of the run (built once from the typed results); :func:`with_findings` puts it first (after
the cover) among a report's sheets. Only the areas change with the unit system (m^2 or
ft^2); angles stay in deg, airspeeds in kt, ratios and rates as they are, as on every other
sheet.
"""

from __future__ import annotations

from slingloads.io.common.excel import Section
from slingloads.io.common.report import in_report_units, report_unit
from slingloads.io.common.units import unit_label

SHEET = "Findings"
NOTE = ("The questions this run answers, one answer each, the same table in every report of "
        "the run: the value with its unit, what the verdict compares it with (reference, same "
        "unit) and where it comes from. 'not run': no analysis of this run answers it. Loads "
        "here (Nz, exceedance ratios) are LIMIT loads.")


def findings_table(findings, units="SI"):
    """The findings as a table in report units (areas converted).

    Parameters
    ----------
    findings : Findings
    units : str
        ``"SI"`` or ``"US"``.

    Returns
    -------
    pandas.DataFrame
    """
    frame = findings.to_frame()
    areas = frame["unit"] == "m^2"
    for column in ("value", "reference"):
        frame.loc[areas, column] = [float(in_report_units(float(v), "area", units))
                                    for v in frame.loc[areas, column]]
    frame.loc[areas, "unit"] = unit_label(report_unit("area", units))
    return frame


def findings_sheet(findings, units="SI"):
    """The Findings sheet's content: one table (its title in the page header, the note under
    it)."""
    return [Section("Findings of this run, one answer per question (LIMIT)",
                    findings_table(findings, units), note=NOTE)]


def with_findings(sheets, findings, units="SI"):
    """``sheets`` with the Findings sheet first (``sheets`` itself when ``findings`` is
    None)."""
    if findings is None:
        return sheets
    return {SHEET: findings_sheet(findings, units), **sheets}
