"""The wing layout: a footprint painted as wings along a corridor skeleton (the paper's offices and schools)."""

from realistic_indoor.generator.wings.layout import SkeletonPainter, wing_layout
from realistic_indoor.generator.wings.style import OFFICE_WINGS, SCHOOL_WINGS, WingStyle

__all__ = ["OFFICE_WINGS", "SCHOOL_WINGS", "SkeletonPainter", "WingStyle", "wing_layout"]
