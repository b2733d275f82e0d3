"""The sheets of the loads workbook: the Summary's findings and every sheet's sections.

What this module guarantees: each verdict on the Summary follows from numbers shown beside
it or on a named sheet (the hook angle against CS 29.865(a) with the lateral study's
evidence, the towed cables against the hook cone, the exceedances over the previous
envelope and where that envelope comes from, the free-free closure); the sheets come in
the report's order, made of the tables of :mod:`slingloads.io.loads.tables`.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd

from slingloads.analyses.loads import CLOSURE_TOLERANCE
from slingloads.analyses.sfbm import COMPONENTS
from slingloads.io.common.decision import decision_section
from slingloads.io.common.excel import Section
from slingloads.io.common.report import (
    in_report_units,
    report_unit,
    warning_sections,
)
from slingloads.io.common.units import unit_label
from slingloads.io.loads.tables import (
    CASE_SOURCES,
    UNBOUNDED_RATIO,
    attitude_table,
    case_report_tables,
    closure_passes,
    closure_table,
    comparison_report_table,
    convert_by_component,
    envelope_report_table,
    envelope_wide_table,
    exceedance_wide_table,
    governing_report_table,
    hook_direction_note,
    hook_direction_table,
    hull_report_table,
    inputs_tables,
    outside_text,
    previous_station_status,
    report_unit_label,
    study_table,
    towed_note,
    towed_outside,
    towed_summary_table,
)

#: Regulatory hook angle of CS 29.865(a): the off-axis hook loads are inclined 30 deg from
#: the mast unless a smaller angle is shown not to be exceeded in service. [deg]
CS29865_ANGLE_DEG = 30.0



def hook_angle_finding(result, lateral=None, justification=""):
    """The hook-cone inclinations against CS 29.865(a), with the evidence they rest on.

    Parameters
    ----------
    result : LoadsResult
    lateral : object, optional
        The lateral study of the same run (a result with ``study.recommended_angle`` [rad],
        ``study.max_load_angle`` [rad], ``study.margin`` and ``study.pendulums``), or None.
    justification : str
        The Study sheet's 'hook angle justification' (a reference to the evidence).

    Returns
    -------
    (str, str)
        ``(verdict, evidence)``: the verdict starts with ``FLAG`` when an inclination used is
        below 30 deg, or the lateral directions are inclined less than the lateral study
        recommends.
    """
    hook = result.study.hook
    ref = CS29865_ANGLE_DEG
    fore_aft = float(np.degrees(hook.angle))
    side = float(np.degrees(hook.lateral))
    if lateral is not None:
        st = lateral.study
        rec, peak = float(np.degrees(st.recommended_angle)), float(np.degrees(st.max_load_angle))
        said = (f"recommended design angle {rec:.1f} deg for the lateral directions"
                if np.isfinite(rec) else "no design angle (see its verdict)")
        evidence = (f"Lateral-step pendulum study of this run: largest load angle from the "
                    f"mast {peak:.1f} deg over {len(st.pendulums)} cases (carrier motions x "
                    f"rope lengths x bodies x stated ranges), margin {st.margin:g}, "
                    f"{said}; see the lateral report.")
    else:
        rec = peak = None
        evidence = ("No lateral-step pendulum study in this run: nothing here shows that a "
                    "smaller angle cannot be exceeded in service (run it with 'run lateral' = "
                    "yes).")
    if justification:
        evidence += f" Study sheet 'hook angle justification': {justification}"
    below = [(name, angle) for name, angle in (("fore-and-aft and diagonal", fore_aft),
                                                ("lateral", side)) if angle < ref - 1e-9]
    if below:
        which = "; ".join(f"{name} directions {angle:.1f} deg" for name, angle in below)
        verdict = (f"FLAG: hook loads inclined less than the {ref:.0f} deg of CS 29.865(a) from "
                   f"the vertical ({which}). A smaller angle is allowed only if it is shown "
                   f"that it cannot be exceeded in service.")
        if fore_aft < ref - 1e-9:
            verdict += (" The lateral-step study covers the lateral directions only: the "
                        "fore-and-aft angle needs its own evidence.")
        if rec is not None and rec > side + 1e-9:
            verdict += (f" The lateral study recommends {rec:.1f} deg: the lateral angle used is "
                        f"NOT covered by it.")
        elif rec is not None and side < ref - 1e-9:
            verdict += (f" The lateral study's recommended {rec:.1f} deg is within the lateral "
                        f"angle used, provided its motions cover the operation being "
                        f"certified.")
    elif rec is not None and rec >= 90.0:
        verdict = (f"FLAG: the lateral study finds load angles up to {peak:.1f} deg from the "
                   f"mast (recommended {rec:.1f} deg with its margin), beyond the {side:.1f} deg "
                   f"used for the lateral hook loads: the {ref:.0f} deg of CS 29.865(a) is not "
                   f"conservative for the motions swept, and no hook cone can be built at "
                   f"{rec:.1f} deg. Restrict the carrier motions or rope lengths, or "
                   f"substantiate the lateral hook loads otherwise.")
    elif rec is not None and rec > side + 1e-9:
        verdict = (f"FLAG: the lateral study recommends {rec:.1f} deg, more than the {side:.1f} "
                   f"deg used for the lateral hook loads: rerun the loads at {rec:.1f} deg.")
    else:
        verdict = (f"Hook loads inclined {fore_aft:.1f} deg from the vertical"
                   + (f" ({side:.1f} deg laterally)" if abs(side - fore_aft) > 1e-9 else "")
                   + f", the {ref:.0f} deg of CS 29.865(a) or more.")
    return verdict, evidence



def exceedance_findings(result, source=""):
    """Lines on the exceedance check: how many stations exceed, and where the previous
    envelope comes from."""
    comparison = result.comparison()
    if comparison is None:
        return ["No previous design envelope given: no exceedance check."]
    over = comparison[comparison["exceeds"]]
    worst = comparison["exceedance ratio"].replace(np.inf, np.nan)
    status = previous_station_status(result)
    interpolated = sum(s == "INTERPOLATED" for s in status)
    lines = [f"{len(over)} of {len(comparison)} station x component entries exceed the "
             f"previous design envelope (largest finite ratio "
             f"{np.nanmax(worst.to_numpy(float)) if worst.notna().any() else 0:.3f}); "
             f"components: {', '.join(sorted(set(over['component']))) or 'none'}. Sheets "
             "Exceedance and ExceedanceDetail."]
    if interpolated:
        lines.append(f"{interpolated} cut station(s) are not stations of the previous envelope:"
                     " its values there are INTERPOLATED linearly (marked on the sheets).")
    lines.append("Previous envelope: " + (source or "source not stated (Study sheet "
                                          "'previous envelope source')."))
    return lines



def sheets_columns(sheets, name):
    """Column names of the tables of one sheet."""
    content = sheets.get(name)
    if isinstance(content, pd.DataFrame):
        return list(content.columns)
    if isinstance(content, str) or content is None:
        return []
    return [c for s in content if s.table is not None for c in s.table.columns]



def nastran_sheet(deck):
    """The *Nastran* sheet: the file's settings, the subcase -> case id table, the grids."""
    return [Section("Nastran input file (<stem>-loads.bdf): settings", deck.settings_table()),
            Section("Subcases: number, LOAD set and the case id each stands for",
                    deck.subcase_table(),
                    note="Nastran labels hold printable ASCII; a longer or non-ASCII case id "
                         "is shortened and ends in '~' and a checksum."),
            Section("Grids (model axes, file units) and CONM2 elements", deck.grid_table())]



def workbook_sheets(result, units, hull_pairs, stations, findings, checks=None):
    """The sheets of the loads workbook, in order."""
    study = result.study
    verdict, evidence = hook_angle_finding(result, findings.get("lateral"),
                                           findings.get("hook angle justification", ""))
    closure = closure_table(result, units)
    closure_line = (f"Free-free closure: {'PASS' if closure_passes(result) else 'FAIL'} "
                    f"(largest residual against {CLOSURE_TOLERANCE:g} x the load scale).")
    outside = towed_outside(result)
    hook_handoff = findings.get("hook angle handoff")
    notes = [verdict, *([hook_handoff.describe()] if hook_handoff is not None else []),
             "Evidence: " + evidence,
             *(["FLAG: towed cables " + outside_text(outside)] if outside else []),
             *[f"FLAG: {line}" for line in result.towed_findings()],
             *exceedance_findings(result, findings.get("previous envelope source", "")),
             closure_line]
    summary = [
        Section("Summary of the LIMIT loads analysis: findings", note="\n".join(notes)),
        *warning_sections(findings.get("warnings", ())),
    ]
    if checks is not None and len(checks):
        failed = checks["status"] != "ok"
        lines = [f"WARNING: {n}" for n in checks["note"][failed]] or [
            "Every check against the other analyses of this run passes: "
            + " ".join(checks["note"])]
        summary.append(Section(  # the notes above the table, which stays narrow for print
            "Consistency with the other analyses of this run",
            checks.drop(columns=["note"], errors="ignore"), note="\n".join(lines)))
    if hook_handoff is not None:
        summary.append(Section("Lateral hook angle: the lateral study's hand-off to the loads",
                               hook_handoff.to_frame()))
    if study.parachute is not None:  # the loads' parachute: the study's one decision on it
        summary += decision_section(findings.get("parachute decision"), units)
    summary += [
        Section("Study settings", study_table(result, units)),
        Section("Attitude (earth vertical in airframe axes)", attitude_table(result),
                note=result.attitude.describe() + ". Gravity, the vertical hook case and the "
                     "hook cone are taken about this vertical."),
        Section("Hook-load directions (CS-29.865)", hook_direction_table(result),
                note=hook_direction_note(result)),
        Section("Towed-flight equilibrium cases: trimmed attitude and cable angles",
                towed_summary_table(result),
                note=towed_note(result)),
        Section("Closure check (free-free equilibrium)", closure),
    ]
    tables = inputs_tables(result, units)
    total = float(in_report_units(study.airframe.mass_items.total_mass, "mass", units))
    inputs = [
        Section("Inputs of the LIMIT loads analysis: mass items, cut stations, hardpoints",
                note="As read from the input workbook (Study, MassItems, Stations, Hardpoints "
                     "sheets), in the report's units."),
        Section("Mass items (transport configuration)", tables["mass items"],
                note=f"{len(tables['mass items'])} items, total {total:,.1f} "
                     f"{report_unit_label('mass', units)}."),
        Section("Cut stations", tables["stations"]),
        Section("Hardpoints (where external loads enter)", tables["hardpoints"],
                note="Weight: share of the hub load taken by each mast foot in the "
                     "rigid-body (RBE3-like) distribution."),
        Section("Loads reference axis and mast axis", tables["axes"]),
    ]
    factor = study.ultimate_factor
    envelope = [
        Section("Envelope of LIMIT loads: max and min of each component over every case, with "
                "the critical case",
                note="Correlated loads of each critical case: sheet Correlated. ULTIMATE "
                     "loads: sheet Ultimate."),
        Section("Governing cases: largest |LIMIT load| of each component",
                governing_report_table(result, units)),
        Section("Shear forces (LIMIT): Vx axial (> 0 tension), Vy and Vz",
                envelope_wide_table(result, COMPONENTS[:3], units)),
        Section("Moments (LIMIT): Mx torsion, My and Mz bending about the loads reference "
                "axis", envelope_wide_table(result, COMPONENTS[3:], units)),
    ]
    correlated = [Section("Envelope of LIMIT loads with the correlated loads of the critical "
                          "case (one row per station, component and bound)",
                          envelope_report_table(result, units))]
    wide = exceedance_wide_table(result, units)
    if wide is not None:
        source = findings.get("previous envelope source", "")
        exceedance = [Section(
            "Exceedance of the LIMIT envelope over the previous design envelope, by station",
            wide,
            note="ratio = max(new max+ / previous max+, |new min-| / |previous min-|); above 1 "
                 "(red) the new envelope exceeds the previous one; "
                 f"'{UNBOUNDED_RATIO}' (red): a new load where the previous envelope is 0. "
                 "'previous values': given at "
                 "this station, or INTERPOLATED linearly between the previous envelope's "
                 "stations. Where the previous envelope comes from: "
                 + ("Summary, findings." if source else "not stated (Study sheet 'previous "
                    "envelope source')."))]
        detail = [Section("LIMIT loads over the previous design envelope: exceedance at every "
                          "station and component", comparison_report_table(result, units))]
    else:  # one page says so (the Summary too); the detail sheet would repeat it
        exceedance, detail = "no previous envelope given", None
    ultimate = [
        Section(f"Envelope of ULTIMATE loads = {factor:g} x LIMIT loads",
                note=f"Ultimate factor of safety {factor:g} (CS 29.303). Only this sheet holds "
                     "ULTIMATE loads; every other sheet, plot and CSV file holds LIMIT loads."),
        Section(f"Shear forces (ULTIMATE = {factor:g} x LIMIT)",
                envelope_wide_table(result, COMPONENTS[:3], units, ultimate=True)),
        Section(f"Moments (ULTIMATE = {factor:g} x LIMIT)",
                envelope_wide_table(result, COMPONENTS[3:], units, ultimate=True)),
    ]
    hulls = ([Section("2-D envelopes (convex hulls) of LIMIT loads at chosen stations",
                      note="Vertices counter-clockwise from the case of the smallest first "
                           "component; every case inside or on the hull. "
                           "Stations and pairs: Study sheet 'hull stations', 'hull pairs'.")]
             + [Section(f"{a}-{b} convex hull vertices, LIMIT loads",
                        hull_report_table(result, (a, b), stations, units))
                for a, b in hull_pairs]) if hull_pairs else "no hull pair requested"
    cases, factors = case_report_tables(result, units)
    counts = cases["source"].value_counts()
    origin = ", ".join(f"{counts[s]} {s}" for s in CASE_SOURCES if s in counts)
    cases_sheet = [Section(
        f"LIMIT load cases ({len(cases)}: {origin}): hook direction x "
        "aerodynamic point x parachute, cable angles, description", cases),
        Section(f"LIMIT load factors of the load cases ({len(cases)}), angular accelerations "
                "and closure residuals", factors, sheet="LoadFactors")]
    sheets = {
        "Summary": summary,
        "Inputs": inputs,
        "LoadCases": cases_sheet,
        "Envelope": envelope,
        "Correlated": correlated,
        "Exceedance": exceedance,
        "ExceedanceDetail": detail,
        "Ultimate": ultimate,
        "Hulls": hulls,
    }
    return {name: content for name, content in sheets.items() if content is not None}


_NUMBER = re.compile(r"(?<![\w.+-])-?\d+(?:\.\d+)?(?![\w.])")


def _angle_text(value):
    """An angle of the hand-off table [deg] at the report's 0.1 deg: a number rounded, every
    number of a range written the same (``"theta -28.01 to -12.05"`` -> ``"theta -28.0 to
    -12.1"``); a text without numbers unchanged.

    Examples
    --------
    >>> _angle_text("hand points, and -32.42 to 0 (DYN-* points)")
    'hand points, and -32.4 to 0.0 (DYN-* points)'
    """
    if isinstance(value, str):
        return _NUMBER.sub(lambda m: f"{float(m.group(0)):.1f}", value)
    return value



def dynamics_sections(result, comparison, units="SI"):
    """The *Dynamics* sheet: what the campaign's dynamics changed in the cases, and the
    largest loads of the hand-entered cases against those of the cases from the dynamics."""
    from slingloads.analyses.campaign import comparison_as_run, loads_comparison

    table = comparison_as_run(comparison, result.study.hook)
    if units == "US":
        for unit, kind in (("N", "force"), ("m^2", "area")):
            rows = table["unit"] == unit
            label = unit_label(report_unit(kind, units))
            for column in ("hand-entered", "dynamics reached", "with margin",
                           "used in the loads"):
                values = pd.to_numeric(table.loc[rows, column], errors="coerce")
                table.loc[rows, column] = in_report_units(values.to_numpy(float), kind, units)
            table.loc[rows, "unit"] = label
    columns = [c for c in ("hand-entered", "dynamics reached", "with margin",
                           "used in the loads", "note") if c in table.columns]
    degrees = table["unit"] == "deg"
    for column in columns:  # an angle to 0.1 deg, in its ranges as in its numbers
        table.loc[degrees, column] = table.loc[degrees, column].map(_angle_text)
    sections = [Section("Hand-entered against the dynamics (the campaign's hand-off)", table,
                        note=result.study.dynamics.note if result.study.dynamics else "")]
    loads = loads_comparison(result)
    if loads is not None:
        loads = convert_by_component(loads.drop(columns="kind"),
                                     ["hand-entered cases", "dynamics cases"], units)
        sections.append(Section(
            "Largest |limit load| over the airframe: hand-entered cases against the cases "
            "from the dynamics (LoadCases column 'source')", loads))
    return sections
