"""The wing layout shared by offices and schools: corridor skeleton, room strips, service cores."""

from realistic_indoor.generator.wings.layout import wing_plan
from realistic_indoor.generator.wings.style import OFFICE_STYLE, SCHOOL_STYLE, WingStyle

__all__ = ["OFFICE_STYLE", "SCHOOL_STYLE", "WingStyle", "wing_plan"]
