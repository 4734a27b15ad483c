"""Realism validator: the paper's statistics for any set of buildings (pure functions)."""

from realistic_indoor.validator.features import RoomFeatures, all_room_features, room_features
from realistic_indoor.validator.tables import label_table

__all__ = ["RoomFeatures", "all_room_features", "label_table", "room_features"]
