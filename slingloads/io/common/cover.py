"""The identity of a report: its cover sheet, page headers and footers.

A report that goes into a substantiation document must say what it is, what it was computed
from and by what: :class:`ReportInfo` holds the report's title, what the analysis covers,
the input file (name, SHA-256, modification time), the slingloads version and source
revision, the run date, and the free fields project, document number, author and checker
read from the Study sheet. :func:`cover_sections` lays them out, with the list of sheets and
the conventions, as the first sheet of every report workbook
(:func:`slingloads.io.common.excel.write_workbook`).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass, field, replace
from datetime import datetime
from functools import lru_cache
from pathlib import Path

import slingloads

#: Name of the cover sheet.
COVER_SHEET = "Cover"
#: Study-sheet parameters printed on the cover, in order (free text, default empty).
IDENTIFICATION = ("project", "document number", "author", "checker")

#: Conventions every report states (analysis-specific lines are added by each report).
CONVENTIONS = (
    "Axes: x aft (fuselage station), y right (butt line), z up (water line), from the "
    "airframe datum. SI inside; this report in the units stated above (angles in degrees).",
    "Aerodynamic angles: alpha > 0 nose up, beta > 0 wind from the right; Cn > 0 nose right.",
    "Attitude angles, in every report and analysis: aerospace (pilot's) Euler angles, yaw > 0 "
    "nose right, pitch > 0 nose up, roll > 0 right side down (R = Rz(-yaw) Ry(pitch) "
    "Rx(-roll) in the axes above; right-handed angles (rx, ry, rz) = (-roll, pitch, -yaw)); "
    "body rates p, q, r right-handed about the body axes; cable swing angles > 0 with the hub "
    "aft of / right of the hook.",
    "Full statement of the axes, signs and load definitions: docs/conventions.md of the "
    "slingloads version above.",
)


def _stamp(moment):
    """A date and time as an engineer writes it, with its offset from UTC."""
    return moment.isoformat(sep=" ", timespec="seconds")


def now_stamp():
    """The current local date and time, with its UTC offset (``2026-11-23 11:44:47+01:00``)."""
    return _stamp(datetime.now().astimezone())


def file_modified(path):
    """Modification time of a file (local time with UTC offset), or ``"unknown"``."""
    try:
        return _stamp(datetime.fromtimestamp(os.stat(path).st_mtime).astimezone())
    except OSError:
        return "unknown"


@lru_cache(maxsize=1)
def source_revision():
    """``git describe`` of the source checkout slingloads runs from, or None.

    None when slingloads is installed from a package (no ``.git`` beside the package), when
    git is not installed, or when git fails: the revision is a courtesy, never a reason to
    fail a run.
    """
    root = Path(slingloads.__file__).resolve().parents[1]
    if not (root / ".git").exists():
        return None
    git = shutil.which("git")
    if git is None:
        return None
    try:
        done = subprocess.run([git, "-C", str(root), "describe", "--always", "--dirty",
                               "--tags"], capture_output=True, text=True, timeout=10,
                              check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    text = done.stdout.strip()
    return text if done.returncode == 0 and text else None


@dataclass(frozen=True)
class ReportInfo:
    """What identifies a report: printed on its cover and in every page header and footer.

    Attributes
    ----------
    title : str
        Report title (``"Structural loads report"``).
    analysis : str
        What the analysis is and what it covers, a few sentences.
    study : str
        Study name (Study sheet ``study name``).
    input_name : str
        Input file name (no directory).
    input_sha256 : str
        SHA-256 of the input file, hex.
    input_modified : str
        Modification time of the input file.
    units : str
        Unit system of the report, e.g. ``"SI (m, kg, N, N m)"``.
    run_date : str
        When the report was produced.
    version : str
        slingloads version.
    revision : str or None
        Source revision (``git describe``) when slingloads runs from a checkout.
    project, document, author, checker : str
        Free fields from the Study sheet.
    conventions : tuple of str
        Lines on the axes, signs, limit and ultimate loads, in addition to
        :data:`CONVENTIONS`.
    files : tuple of str
        The other files of the report (CSV tables, PNG plots).
    """

    title: str
    analysis: str
    study: str
    input_name: str
    input_sha256: str = ""
    input_modified: str = "unknown"
    units: str = "SI"
    run_date: str = field(default_factory=now_stamp)
    version: str = slingloads.__version__
    revision: str | None = field(default_factory=source_revision)
    project: str = ""
    document: str = ""
    author: str = ""
    checker: str = ""
    conventions: tuple = ()
    files: tuple = ()

    @property
    def software(self):
        """``slingloads <version> (<revision>)``."""
        rev = f" ({self.revision})" if self.revision else ""
        return f"slingloads {self.version}{rev}"

    def with_files(self, files):
        """A copy listing ``files`` as the report's other files."""
        return replace(self, files=tuple(files))


def report_info(study, *, title, analysis, units, conventions=(), files=()):
    """The :class:`ReportInfo` of a report of a study.

    Parameters
    ----------
    study : Study
        Gives the study name and, from its source, the input file, its SHA-256, the run date
        and the free fields project, document number, author and checker.
    title, analysis : str
    units : str
        ``"SI"`` or ``"US"``.
    conventions, files : sequence of str

    Returns
    -------
    ReportInfo
    """
    source = study.source
    ident = source.identification
    return ReportInfo(
        title=title, analysis=analysis, study=study.name,
        input_name=Path(source.path).name, input_sha256=source.sha256,
        input_modified=file_modified(source.path), units=unit_system_text(units),
        run_date=source.run_date or now_stamp(),
        project=ident.get("project", ""), document=ident.get("document number", ""),
        author=ident.get("author", ""), checker=ident.get("checker", ""),
        conventions=tuple(conventions), files=tuple(files))


def input_digest(study):
    """What a report is computed from: input file, SHA-256, study, analyses, version, and
    the warnings on the inputs (``{item: entry}``)."""
    source = study.source
    out = {"input workbook": Path(source.path).name, "SHA-256": source.sha256,
           "study": study.name, "analyses": ", ".join(study.asked),
           "slingloads version": slingloads.__version__}
    for k, text in enumerate(source.warnings, start=1):
        out[f"warning {k}"] = text
    return out


def info_from_digest(digest, *, title, analysis, study, units, conventions=(), files=()):
    """A :class:`ReportInfo` from an inputs digest ``{item: entry}`` (reports written through
    the Python API without a workbook study)."""
    digest = dict(digest or {})
    name = next((str(digest[k]) for k in ("input workbook", "input file", "input")
                 if k in digest), "(not from a workbook)")
    return ReportInfo(title=title, analysis=analysis, study=study, input_name=name,
                      input_sha256=str(digest.get("SHA-256", "")),
                      units=unit_system_text(units), conventions=tuple(conventions),
                      files=tuple(files))


def unit_system_text(units):
    """``"SI (m, kg, N, N m, ...)"`` or ``"US customary (in, lb, lbf, lbf in, ...)"``."""
    return {"SI": "SI (m, kg, N, N m, kg m^2, m/s; airspeeds in kt, angles in deg)",
            "US": "US customary (in, lb, lbf, lbf in, lb in^2, ft/s; airspeeds in kt, "
                  "altitudes in ft, angles in deg)"}.get(units, units)


def cover_sections(info, sheets):
    """The cover's blocks: ``(title, note, table or None)``.

    Parameters
    ----------
    info : ReportInfo
    sheets : sequence of (str, str)
        ``(sheet name, what it holds)`` of the workbook's other sheets.

    Returns
    -------
    list of (str, str, pandas.DataFrame or None)
    """
    import pandas as pd  # here: the study reader takes the cover's fields, not its tables

    entry = pd.DataFrame([
        ("project", info.project),
        ("document number", info.document),
        ("author", info.author),
        ("checker", info.checker),
        ("study", info.study),
        ("input workbook", info.input_name),
        ("input SHA-256", info.input_sha256),
        ("input modified", info.input_modified),
        ("slingloads version", info.version),
        ("source revision", info.revision or "none (not run from a source checkout)"),
        ("run date", info.run_date),
        ("report units", info.units),
    ], columns=["item", "entry"])
    listing = pd.DataFrame(list(sheets), columns=["sheet", "content"])
    blocks = [("", info.analysis, None),
              ("Identification", "", entry),
              ("Sheets", "", listing)]
    if info.files:
        blocks.append(("Other files of this report", ", ".join(info.files), None))
    blocks.append(("Conventions", "\n".join((*info.conventions, *CONVENTIONS)), None))
    return blocks
