"""The campaign: the multibody model swept over the operating envelope (paper sections 4.4, 4.5,
5 and 6). Parachute selection with its governing condition, sensitivity, stability maps,
transport without parachute and the dynamics handed to the structural loads; runs executed in
batches on local processes or a Dask cluster, with a store of finished runs.

>>> from slingloads.analyses.campaign import Campaign, CampaignSetup, run_campaign

Method: ``docs/campaign.md``.
"""

from .campaign import Campaign, CampaignResult, RunSettings, neutral_check, run_campaign
from .execution import (
    SCHEDULER_TIMEOUT,
    DaskCluster,
    InProcess,
    LocalProcesses,
    MemoryStore,
    execute,
    make_executor,
)
from .handoff import (
    HOOK_SOURCES,
    Handoff,
    comparison_as_run,
    loads_comparison,
    loads_from_dynamics,
)
from .keys import KeyMaker, canonical, code_digest
from .loads_envelope import MARGIN, DynamicsEnvelope, dynamics_envelope
from .matrix import (
    CARRIERS,
    CONDITION_COLUMNS,
    MANOEUVRES,
    ROW_FACTORS,
    CampaignMatrix,
    Factors,
    MassCase,
)
from .metrics import HISTORY_LABELS, YAW_SHARE
from .no_parachute import (
    GUST_DELAY,
    GUST_DURATION,
    GUST_SPEED,
    GUST_TARGETS,
    RAMP_TARGETS,
    NoParachuteResult,
    NoParachuteStudy,
    sample_full_tail_system,
    speed_limits,
)
from .selection import (
    MAX_HALF_TIME,
    MIN_DAMPING,
    Selection,
    SelectionCriteria,
    damped_runs,
    select_parachute,
    stable_runs,
)
from .sensitivity import (
    FACTORS,
    base_condition,
    carrier_comparison,
    sensitivity_tables,
    sweep_runs,
)
from .setup import (
    DEFAULT_FREE_CARRIER,
    CampaignSetup,
    neutral_area_of,
    scaled_body,
    towed_trim_of,
    trim_text,
    yaw_model_of,
)
from .stability_map import MapSettings, StabilityMap, stability_map

__all__ = [
    "CARRIERS", "CONDITION_COLUMNS", "DEFAULT_FREE_CARRIER", "FACTORS", "HISTORY_LABELS",
    "HOOK_SOURCES", "Handoff", "comparison_as_run", "loads_comparison", "loads_from_dynamics",
    "MANOEUVRES",
    "GUST_DELAY", "GUST_DURATION", "GUST_SPEED", "GUST_TARGETS",
    "MARGIN", "MAX_HALF_TIME", "MIN_DAMPING", "RAMP_TARGETS", "ROW_FACTORS",
    "SCHEDULER_TIMEOUT", "YAW_SHARE",
    "Campaign", "CampaignMatrix", "CampaignResult", "CampaignSetup", "DaskCluster",
    "DynamicsEnvelope", "Factors", "InProcess", "KeyMaker", "LocalProcesses", "MapSettings",
    "MassCase", "MemoryStore", "NoParachuteResult", "NoParachuteStudy", "RunSettings",
    "Selection", "SelectionCriteria", "StabilityMap", "base_condition", "canonical",
    "carrier_comparison", "code_digest", "damped_runs", "dynamics_envelope", "execute",
    "make_executor", "neutral_area_of", "neutral_check", "run_campaign",
    "sample_full_tail_system", "scaled_body", "select_parachute", "sensitivity_tables",
    "speed_limits", "stability_map", "stable_runs", "sweep_runs", "towed_trim_of", "trim_text",
    "yaw_model_of",
]
