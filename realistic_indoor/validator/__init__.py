"""Realism validator: the paper's statistics for any set of buildings (pure functions).

- :func:`room_features`, :func:`label_table`, :func:`render_label_tables`: the feature vector
  per room and the paper's Table 1 for a set, as a terminal table, Markdown, CSV or JSON;
- :func:`connectivity`, :func:`set_connectivity` and the functions of
  :mod:`~realistic_indoor.validator.connectivity`: corridors, dead ends, room mazes, paths;
- :func:`infer_labels`: semantic labels for plans that lack them;
- :func:`paper_reference`, :func:`fitted_reference`, :func:`realism_score`: one score against
  real buildings, with the worst deviations in words;
- :func:`two_sample_test`: can a classifier tell two sets apart?
- :func:`scale_check`: plans whose scale looks wrong;
- :func:`house_check`, :func:`house_summary`: house plans against the house programme of
  published housing statistics;
- :func:`compare_sets`, :func:`render_comparison`, :func:`plot_comparison`: all of it for several
  sets of maps side by side (what ``realistic-indoor validate`` prints and draws).

See ``docs/validator.md`` for every definition.
"""

from realistic_indoor.models.scale import ScaleFlag, scale_check
from realistic_indoor.validator.compare import Comparison, SetReport, compare_sets
from realistic_indoor.validator.connectivity import Connectivity, connectivity, room_mazes, set_connectivity
from realistic_indoor.validator.features import RoomFeatures, all_room_features, room_features
from realistic_indoor.validator.house_programme import HouseCheck, HouseSummary, house_check, house_summary
from realistic_indoor.validator.label_inference import infer_labels, lacks_labels, size_thresholds
from realistic_indoor.validator.plan_sets import PlanSet, load_plan_set
from realistic_indoor.validator.reference import Reference, fitted_reference, paper_reference
from realistic_indoor.validator.report import render_comparison
from realistic_indoor.validator.score import RealismScore, ScoreConfig, realism_score
from realistic_indoor.validator.tables import label_table, render_label_tables
from realistic_indoor.validator.two_sample import TwoSampleResult, two_sample_test

__all__ = [
    "Comparison",
    "Connectivity",
    "HouseCheck",
    "HouseSummary",
    "PlanSet",
    "RealismScore",
    "Reference",
    "RoomFeatures",
    "ScaleFlag",
    "ScoreConfig",
    "SetReport",
    "TwoSampleResult",
    "all_room_features",
    "compare_sets",
    "connectivity",
    "fitted_reference",
    "house_check",
    "house_summary",
    "infer_labels",
    "label_table",
    "lacks_labels",
    "load_plan_set",
    "paper_reference",
    "plot_comparison",
    "realism_score",
    "render_comparison",
    "render_label_tables",
    "room_features",
    "room_mazes",
    "scale_check",
    "set_connectivity",
    "size_thresholds",
    "two_sample_test",
]


def __getattr__(name: str):
    if name == "plot_comparison":  # matplotlib only when a figure is asked for
        from realistic_indoor.validator.plot import plot_comparison

        return plot_comparison
    raise AttributeError(f"module 'realistic_indoor.validator' has no attribute {name!r}")
