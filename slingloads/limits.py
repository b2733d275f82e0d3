"""Upper limits on what an input may ask for: one place for every bound on size and magnitude.

slingloads reads workbooks that may come from anyone. Every quantity that sets the size of the
work (rows of a sheet, load cases, stations, runs, time steps, stored samples) or that could
overflow a computation is bounded here, and each bound is checked *before* the memory or time
it guards is spent, with an error located at the cell that sets it. The bounds are generous
for engineering use (ten to a hundred times the paper's study) and small enough that no input
of under 1 MB makes a command use more than about 1 GB of memory or a minute of time before it
is refused or finished (``docs/inputs-and-outputs.md`` gives the reasons for each value).

The readers apply them through the schema (:mod:`slingloads.io.common.schema`: ``Column`` and
``Parameter`` bounds, ``TableSheet.max_rows``); the template states them beside each column and
parameter; the analyses check their own work products (runs x steps) as a last guard.
"""

from __future__ import annotations

import math

MiB = 1024 * 1024

# ---- input files -------------------------------------------------------------------------
#: Largest input workbook on disk. [bytes]
MAX_WORKBOOK_BYTES = 64 * MiB
#: Largest uncompressed content of a workbook (all its parts). [bytes]
MAX_UNCOMPRESSED_BYTES = 128 * MiB
#: Largest uncompressed part of a workbook, by kind of part. [bytes] Worksheets are streamed;
#: shared strings, styles and the other XML parts are parsed whole (openpyxl builds an object
#: per entry, through the safe but slow pure-Python parser of defusedxml); parts that are not
#: parsed (images) count only towards MAX_UNCOMPRESSED_BYTES.
MAX_PART_BYTES = {"worksheet": 64 * MiB, "sharedStrings": 4 * MiB, "styles": 4 * MiB,
                  "other": 4 * MiB}
#: Most parts (files) in a workbook's ZIP container.
MAX_ZIP_MEMBERS = 2000
#: Most cells stored in one read sheet, formatted empty cells included: beyond it the sheet is
#: refused (clear its unused rows and columns) rather than parsed for minutes.
MAX_SHEET_CELLS = 500_000
#: Most XML elements of one read sheet (cells, their values, merged ranges, formats...).
MAX_SHEET_ELEMENTS = 4_000_000
#: Most data rows of a table sheet unless its schema says otherwise.
MAX_TABLE_ROWS = 100_000
#: Most rows of the Study sheet.
MAX_STUDY_ROWS = 2_000
#: Longest text in a cell of an id or name column, and in any other text cell. [characters]
MAX_ID_CHARS = 200
MAX_TEXT_CHARS = 2_000
#: Longest unit string. [characters]
MAX_UNIT_CHARS = 64
#: Largest CSV file a workbook may refer to (carrier time histories). [bytes]
MAX_CSV_BYTES = 32 * MiB
#: Most data rows of such a CSV file.
MAX_CSV_ROWS = 200_000
#: Longest path text in a cell. [characters]
MAX_PATH_CHARS = 1_000

# ---- magnitudes --------------------------------------------------------------------------
#: Largest magnitude of any value of a quantity kind, SI. Far beyond any helicopter (a
#: 100 km length, a 1000 t mass) yet small enough that products of a few of them never
#: overflow: a value such as 1e300 is refused at its cell instead of surfacing later as an
#: infinite residual or a NaN inertia.
MAX_MAGNITUDE = {
    "length": 1e5,                      # m
    "mass": 1e6,                        # kg
    "force": 1e9,                       # N
    "moment": 1e10,                     # N m
    "inertia": 1e9,                     # kg m^2
    "angle": 4 * math.pi,               # rad (two turns)
    "speed": 1e3,                       # m/s
    "acceleration": 1e4,                # m/s^2 (about 1000 g)
    "area": 1e4,                        # m^2
    "density": 1e4,                     # kg/m^3
    "time": 1e6,                        # s
    "frequency": 1e6,                   # rad/s
    "stiffness": 1e12,                  # N/m
    "linear damping": 1e9,              # N s/m
    "rotational damping": 1e10,         # N m s/rad
    "dimensionless": 1e6,               # -
    "integer": 1e9,                     # whole numbers without bounds of their own
}

# ---- airframe geometry -------------------------------------------------------------------
#: Largest |x|, |y|, |z| of any point of the airframe from its datum: mass items, hardpoints,
#: cut stations, aerodynamic points. [m] (The largest helicopters are about 40 m long.)
MAX_COORDINATE = 100.0
#: Largest extent of the mass items along any axis. [m]
MAX_AIRFRAME_SIZE = 80.0

# ---- size of the work --------------------------------------------------------------------
#: Mass items (rows of MassItems).
MAX_MASS_ITEMS = 10_000
#: Cut stations, and aerodynamic load points.
MAX_STATIONS = 500
#: Rows of the aerodynamic coefficient tables (FuselageAero alpha x beta grid, FinAero,
#: ParachuteCD, ChuteWake).
MAX_AERO_ROWS = 20_000
#: Hook-load azimuths.
MAX_HOOK_AZIMUTHS = 360
#: Load cases of the loads analysis (generated and listed).
MAX_LOAD_CASES = 5_000
#: Rows of the SFBM table: load cases x cut stations (the report writes each one).
MAX_SFBM_ROWS = 50_000
#: Load cases x load points (mass items, mast feet, aerodynamic points...): the applied-load
#: arrays hold 6 numbers per pair.
MAX_CASE_POINTS = 5_000_000
#: Runs of the lateral-pendulum sweep: motions x ropes x bodies.
MAX_LATERAL_RUNS = 2_000
#: Steps of one lateral run (run length / RK4 step).
MAX_LATERAL_STEPS = 200_000
#: Run-steps of the lateral sweep: runs x steps (the compiled sweep takes about 0.25 us each,
#: so about 5 s of CPU at the limit).
MAX_LATERAL_RUN_STEPS = 20_000_000
#: Motion-steps of the lateral sweep: distinct motions x steps (each motion's kinematics is
#: evaluated once at every step and tabulated: 3 numbers of 8 bytes, about 100 MB at the limit).
MAX_LATERAL_MOTION_STEPS = 4_000_000
#: Shortest interval between the samples of a time history (a spline through samples closer
#: than this overflows; measured histories are sampled at 1 kHz at most). [s]
MIN_SAMPLE_INTERVAL = 1e-4
#: Samples of one time history (LateralHistory id or CSV file).
MAX_HISTORY_SAMPLES = MAX_CSV_ROWS
#: Stored samples of the critical lateral run's time histories (run length / output step).
MAX_HISTORY_OUTPUT = 200_000
#: Right-hand-side evaluations of one adaptive (solve_ivp) run before it is stopped.
MAX_ODE_EVALUATIONS = 500_000
#: Swept parachute areas.
MAX_CHUTE_AREAS = 500
#: Runs of the parachute sweep: areas x gust shapes.
MAX_CHUTE_RUNS = 2_000
#: Steps of one parachute run: simulation time / time step of the fixed-step RK4, or the steps
#: the adaptive Dormand-Prince 5(4) tries (accepted or rejected; about 1 us each on a core).
MAX_CHUTE_STEPS = 200_000
#: Run-steps of the parachute sweep: runs x steps (with the adaptive step, each run may try
#: this / runs steps when that is fewer than MAX_CHUTE_STEPS).
MAX_CHUTE_RUN_STEPS = 10_000_000
#: Stored samples of the parachute sweep: runs x (simulation time / output interval); each is
#: a row of the histories CSV file.
MAX_CHUTE_SAMPLES = 1_000_000
#: Runs of the parachute sweep with the 'solve_ivp' integrator (one adaptive solve each).
MAX_CHUTE_REFERENCE_RUNS = 50

#: Runs of the multibody model (rows of MultibodyManoeuvres; the paper's list has 14).
MAX_MULTIBODY_RUNS = 200
#: Integration steps of the multibody model over all its runs: runs x (simulation time / fixed
#: step), or, with the adaptive step, runs x the steps the fastest linear mode forces
#: (simulation time x |lambda| / 3.3, the stability bound of the Dormand-Prince pair). The
#: compiled kernel takes about 10 us a run-step on two cores: 3,000,000 is about 30 s.
MAX_MULTIBODY_RUN_STEPS = 3_000_000
#: Stored samples of the multibody model: runs x (simulation time / output interval + 1). Each
#: holds 160 bytes of states (the reported quantities are evaluated when a run's histories are
#: asked for) and is a row of the histories CSV file.
MAX_MULTIBODY_SAMPLES = 200_000
#: Values of one comma-separated list of the campaign (area factors, airspeeds, ...).
MAX_LIST_ITEMS = 50
#: Runs of a campaign: the matrix (product of its lists' lengths and mass cases, or the rows
#: of CampaignRuns) plus the runs without parachute (helicopters x ramps). The paper's
#: campaign has about 1,300 and its full matrix 3,888: with the adaptive step (the default)
#: that matrix takes about a minute on two cores.
MAX_CAMPAIGN_RUNS = 4_000
#: Fixed steps of a campaign over all its runs (with a fixed 'campaign time step'): runs x
#: (run length / time step), about 130,000 per second on two cores, so 8,000,000 is about a
#: minute. The paper's matrix at 0.01 s (23 million run-steps) is refused: it runs with the
#: adaptive step (time step 0, the default) in about a minute, or on a cluster in parts.
MAX_CAMPAIGN_RUN_STEPS = 8_000_000
#: Stored samples of a campaign: runs x (run length / output interval + 1); each is a row of
#: 26 numbers in the run cache and the histories file (written 50 runs at a time; at most
#: about 620 MB uncompressed on disk). The paper's matrix stores 2.3 million.
MAX_CAMPAIGN_SAMPLES = 3_000_000
#: Points of a campaign's stability map: density altitudes x airspeeds x area factors (a trim
#: and an eigenanalysis each, about 20 ms).
MAX_MAP_POINTS = 2_000
#: Local worker processes of a campaign that may be asked for (each holds the compiled
#: kernel; the processes started are also capped by the cores, the memory available and
#: COMMAND_MEMORY).
MAX_WORKERS = 64
#: Memory budget of the arrays of one computation: a batch of runs' samples, or all the runs
#: of the multibody model, or one campaign run. With the loaded libraries (about 300 MB) a
#: command stays under 1 GB (docs/inputs-and-outputs.md, "Memory"). [bytes]
MEMORY_BUDGET = 512 * 2**20
#: Samples of the runs of one campaign batch (the batch is cut to fit). [bytes]
BATCH_MEMORY = 64 * 2**20
#: A worker process with the libraries and compiled kernels loaded (measured about
#: 290 MB). [bytes]
WORKER_BASE_MEMORY = 300 * 2**20
#: Memory budget of a command, all its processes together (docs/inputs-and-outputs.md,
#: "Memory"). [bytes]
COMMAND_MEMORY = 2**30
#: A command's own process and its helper, as the budget of local workers counts them (the
#: 864 runs of 3,600 s measured at most about 420 MiB beside two workers, proportional set
#: sizes: benchmarks/bench_memory.py). [bytes]
COMMAND_OWN_MEMORY = 448 * 2**20
#: A local worker process's own memory beside the libraries it shares with the command's
#: process (measured at most 284 MiB, proportional, a batch and a chunk of drive tables at
#: their largest): so (COMMAND_MEMORY - COMMAND_OWN_MEMORY) / WORKER_OWN_MEMORY = 2 local
#: workers at most. [bytes]
WORKER_OWN_MEMORY = 288 * 2**20
#: Longest time the campaign waits for a scheduler. [s]
MAX_SCHEDULER_TIMEOUT = 600.0

# ---- output folder -----------------------------------------------------------------------
#: Most entries of an output folder (its other files are carried over into each new set).
MAX_OUTPUT_ENTRIES = 20_000


def check_count(count, limit, what, field=None):
    """Return ``count`` if it is at most ``limit``, else raise an InputError naming ``what``.

    Parameters
    ----------
    count : int
    limit : int
    what : str
        What is counted, e.g. ``"lateral runs (motions x ropes x bodies)"``.
    field : str, optional
        The argument that sets the count (``"step"``), so that the io layer can point at the
        cell it came from.

    Raises
    ------
    InputError
        With the rule ``"at most <limit> <what>"`` and the count as value.
    """
    from slingloads.errors import InputError

    if count > limit:
        raise InputError(f"too much work: at most {limit:,} {what} are allowed (limits of "
                         "slingloads)", int(count), field=field)
    return count


def evaluation_budget(function, what, field=None, limit=None):
    """Wrap an ODE right-hand side so that more than ``limit`` calls raise an InputError.

    An adaptive integrator may take any number of steps (a stiff problem, a tolerance at the
    round-off): the budget turns a run that would take hours into a located error.

    Parameters
    ----------
    function : callable
    what : str
        What is integrated, for the message.
    field : str, optional
        The setting to change (``"rtol"``), for the io layer.
    limit : int, optional
        Default :data:`MAX_ODE_EVALUATIONS`.
    """
    from slingloads.errors import InputError

    limit = MAX_ODE_EVALUATIONS if limit is None else limit
    calls = [0]

    def counted(*args):
        calls[0] += 1
        if calls[0] > limit:
            raise InputError(f"too much work: {what} needs more than {limit:,} evaluations "
                             "(limits of slingloads); loosen the tolerance, shorten the run or "
                             "check the inputs for a very stiff case", limit, field=field)
        return function(*args)

    return counted
