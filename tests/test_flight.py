"""The shared flight condition and solver settings.

References: FACTS.md section 2 (ICAO Doc 7488/3 densities; q = 1/2 rho0 V_EAS^2; knot =
0.514444 m/s).
"""

import numpy as np
import pytest

from slingloads.constants import KNOT
from slingloads.errors import InputError
from slingloads.models.flight import FlightCondition
from slingloads.models.integration import SolverSettings


def test_flight_condition_at_10000_ft_density_altitude():
    """ICAO table: rho = 0.90464 kg/m^3 at 10 000 ft (3048 m), sigma = 0.73848. At 100 KEAS
    (51.4444 m/s) by hand: q = 0.5 x 1.225 x 51.4444^2 = 1620.99 Pa; V_TAS = 51.4444 /
    sqrt(0.73848) = 59.865 m/s; and q again as 0.5 rho V_TAS^2 (the other path)."""
    c = FlightCondition(100 * KNOT, density_altitude=3048.0)
    assert c.density == pytest.approx(0.90464, rel=5e-5)
    assert c.density_ratio == pytest.approx(0.73848, rel=5e-5)
    assert c.dynamic_pressure == pytest.approx(1620.99, rel=1e-5)
    assert c.tas == pytest.approx(59.865, rel=1e-4)
    assert 0.5 * c.density * c.tas**2 == pytest.approx(c.dynamic_pressure, rel=1e-12)
    assert c.ias == c.eas and not c.hover


def test_hover_is_zero_airspeed():
    """Hover: no dynamic pressure, no true airspeed, flagged as hover."""
    c = FlightCondition(0.0)
    assert c.hover and c.dynamic_pressure == 0.0 and c.tas == 0.0


@pytest.mark.parametrize("build, match", [
    (lambda: FlightCondition(-1.0), r"airspeed must be >= 0 \[m/s\]: value -1.0"),
    (lambda: FlightCondition(10.0, alpha=float("nan")), r"angle of attack.*value nan"),
    (lambda: FlightCondition(10.0, density_altitude=20000.0), r"troposphere.*20000.0"),
    (lambda: SolverSettings(method="Euler"), r"valid options.*value 'Euler'"),
    (lambda: SolverSettings(step=0.0), r"step must be > 0: value 0.0"),
    (lambda: SolverSettings().with_defaults(dt=0.1), r"take analysis defaults: value 'dt'"),
    (lambda: SolverSettings(t_end=1.0, step=0.3, output_interval=0.3).fixed_grid(),
     r"t_end must be a whole multiple of the step.*1.0"),
    (lambda: SolverSettings(t_end=1.2, step=0.3, output_interval=0.4).fixed_grid(),
     r"output_interval must be a whole multiple of the step.*0.4"),
])
def test_bad_condition_and_settings(build, match):
    """Each rule broken raises InputError naming it and echoing the value."""
    with pytest.raises(InputError, match=match):
        build()


def test_analysis_defaults_fill_only_unset_fields():
    """with_defaults keeps what the user set and fills the rest; the fixed grid then has
    t_end / step steps and output_interval / step steps per stored sample."""
    s = SolverSettings(step=0.02).with_defaults(t_end=10.0, step=0.05, output_interval=0.1)
    assert (s.t_end, s.step, s.output_interval) == (10.0, 0.02, 0.1)
    assert s.fixed_grid() == (500, 5)
    assert np.allclose(s.output_times()[[0, 1, -1]], [0.0, 0.1, 10.0])
