"""Study-sheet parameters and sheets of the parachute sizing (see :mod:`slingloads.io.schema`)."""

from __future__ import annotations

from slingloads.io.schema import Section

SECTION = Section("chute sizing", parameters=(), sheets=())
