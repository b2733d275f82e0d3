"""The one uniqueness rule of ids (slingloads.ids), against the rule as documented in
docs/inputs-and-outputs.md: ids are unique with case (and surrounding spaces) ignored, so that
two ids a reader of the report, or a case-insensitive file system, would take for one are
refused; and the campaign's Python API applies the same rule to its mass cases."""

from __future__ import annotations

import pytest

from slingloads.analyses.campaign import Factors, MassCase
from slingloads.errors import InputError
from slingloads.ids import first_duplicate, id_key


@pytest.mark.parametrize("values, expected", [
    (["NOSE", "tail", "nose"], (0, 2)),
    (["max", "MAX"], (0, 1)),
    (["Free Response", " free response "], (0, 1)),
    (["Straße", "STRASSE"], (0, 1)),  # case folding, not lower(): ß folds to ss
    (["a", "b", "c"], None),
    ([1.0, 2.0, 1.0], (0, 2)),
])
def test_first_duplicate(values, expected):
    """The first repeated id by the documented rule (worked by hand for each list)."""
    assert first_duplicate(values) == expected


def test_id_key_leaves_numbers_alone():
    """Numbers compare as numbers (1 and 1.0 are one id, as in Python)."""
    assert id_key(1) == id_key(1.0) and id_key("A ") == "a"


def test_api_mass_cases_use_the_same_rule():
    """Factors refuses mass cases "max" and "MAX" (same rule as the CampaignMasses sheet)."""
    with pytest.raises(InputError, match="named twice.*case ignored"):
        Factors(masses=(MassCase("max", 2900.0), MassCase("MAX", 2500.0)))
