"""Colours and line weights of plan pictures."""

from __future__ import annotations

from dataclasses import dataclass, field

from realistic_indoor.building.labels import SemanticLabel

__all__ = ["DEFAULT_STYLE", "LABEL_COLOURS", "PlanStyle"]

LABEL_COLOURS: dict[SemanticLabel, str] = {
    SemanticLabel.CORRIDOR: "#EEDD88",
    SemanticLabel.HALL: "#EE8866",
    SemanticLabel.SMALL: "#FFAABB",
    SemanticLabel.MEDIUM: "#99DDFF",
    SemanticLabel.BIG: "#44BB99",
}
"""One fill colour per semantic label, from Paul Tol's colour-blind-safe "light" scheme
(designed for filled areas under dark lines and text)."""


@dataclass(frozen=True)
class PlanStyle:
    """How a plan is drawn.

    Attributes:
        label_colours: Fill colour of rooms, per semantic label.
        wall_colour: Colour of the walls.
        door_colour: Colour of the mark drawn across an interior doorway.
        entrance_colour: Colour of the mark drawn across an exterior door.
        wall_thickness_m: Drawn wall thickness, metres on the plan; converted to points for the
            figure's scale and clipped to ``wall_width_pt``.
        wall_width_pt: Thinnest and thickest wall line allowed, points.
        door_width_factor: Door mark line width relative to the wall line width.
        door_min_width_pt: Thinnest door mark, points (keeps doors visible on large plans).
        entrance_width_factor: Entrance mark line width relative to the wall line width.
        entrance_marker_pt: Size of the triangle pointing into the building at each entrance,
            points.
        function_font_pt: Font size of room function labels, points.
    """

    label_colours: dict[SemanticLabel, str] = field(default_factory=lambda: dict(LABEL_COLOURS))
    wall_colour: str = "#222222"
    door_colour: str = "#0077BB"
    entrance_colour: str = "#CC3311"
    wall_thickness_m: float = 0.15
    wall_width_pt: tuple[float, float] = (0.5, 2.0)
    door_width_factor: float = 1.8
    door_min_width_pt: float = 1.4
    entrance_width_factor: float = 3.0
    entrance_marker_pt: float = 7.0
    function_font_pt: float = 6.0

    def door_width_pt(self, wall_width_pt: float, exterior: bool) -> float:
        """Line width of a door mark (points) for walls drawn ``wall_width_pt`` wide."""
        factor = self.entrance_width_factor if exterior else self.door_width_factor
        return max(wall_width_pt * factor, self.door_min_width_pt * (1.5 if exterior else 1.0))


DEFAULT_STYLE = PlanStyle()
"""The style used when none is given."""
