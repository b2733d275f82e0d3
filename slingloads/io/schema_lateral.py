"""Study-sheet parameters and sheets of the lateral-step pendulum.

See :mod:`slingloads.io.schema`.
"""

from __future__ import annotations

from slingloads.io.schema import Section

SECTION = Section("lateral", parameters=(), sheets=())
